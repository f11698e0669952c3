#ifndef fosls_contact_qp_definiteness_check_h
#define fosls_contact_qp_definiteness_check_h

#include <fosls_contact/qp/constrained_qp.h>

namespace FoslsContact
{
  /**
   * Is the quadratic form of a ConstrainedQP positive definite on the
   * space of non-fixed DoFs?
   *
   * Only the complementarity term can spoil definiteness (paper section 3
   * and 7), and it couples only the contact normal DoFs C (the bounded
   * ones). With I the other non-fixed DoFs, A is positive definite iff
   * A_II is (it is: plain FOSLS with a Dirichlet part) and the Schur
   * complement S = A_CC - A_CI A_II^{-1} A_IC is. S is small and dense:
   * it costs one sparse Cholesky factorization of A_II (SparseCholesky,
   * which refuses an A_II that is not positive definite in floating
   * point) and |C| solves. It runs on a problem of one process (a
   * GatheredQP). The premise that A_II is definite fails
   * where the boundary conditions leave a rigid motion free:
   * least_mode_energy() checks that first.
   */
  struct DefinitenessCheck
  {
    /** Smallest eigenvalue of D^{-1/2} S D^{-1/2}, D = diag(A_CC). */
    double       min_relative_eigenvalue = 1;
    unsigned int n_contact_dofs          = 0;
    /**
     * Whether A_II was positive definite in floating point (its Cholesky
     * factorization went through); if not, S is not formed.
     */
    bool interior_definite = true;
    bool definite() const { return interior_definite && min_relative_eigenvalue > 0; }

    static DefinitenessCheck run(const ConstrainedQP &qp);

    /**
     * The least energy of a combination of @p modes, relative to its
     * diagonal part: min over c of (R c)^T A (R c) / (R c)^T D (R c), with
     * R the modes (set to 0 at the fixed DoFs here) and D = diag(A);
     * @p coefficients(i) is the largest |c_i| (each c scaled to a largest
     * entry of 1) of the stationary combinations with an energy up to
     * @p threshold, or of the least one: the modes that take part in a
     * free motion. For the rigid motions (displacement a
     * translation or rotation, stress 0) the functional's quadratic form
     * vanishes, so where no fixed DoF holds a combination of them the
     * quotient is round-off (and A singular: the minimizer is not
     * unique); one held by a Dirichlet boundary costs the energy of the
     * boundary layer where it is cut off, O(h) relative. Collective.
     */
    static double least_mode_energy(const ConstrainedQP &     qp,
                                    std::vector<LevelVector> &modes,
                                    const double              threshold,
                                    Vector<double> &          coefficients);
  };
} // namespace FoslsContact

#endif
