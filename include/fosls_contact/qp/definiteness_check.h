#ifndef fosls_contact_qp_definiteness_check_h
#define fosls_contact_qp_definiteness_check_h

#include <fosls_contact/qp/constrained_qp.h>

#include <limits>

namespace FoslsContact
{
  /**
   * Is the quadratic form of a ConstrainedQP positive definite on the
   * space of non-fixed DoFs?
   *
   * Only the complementarity term can spoil definiteness (paper section 3
   * and 7), and it couples only the contact normal DoFs C (the bounded
   * ones; with friction the tangential ones of the contact boundary as
   * well, DoFRole::traction and DoFRole::slip). With I the other non-fixed DoFs, A is positive definite iff
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
    /**
     * How far the complementarity weight may be scaled: the largest t with
     * S_0 + t M_CC positive definite, where M is the problem's
     * complementarity part (ConstrainedQP::matrix_compl, assembled with the
     * weight C_compl) and S_0 = S - M_CC the Schur complement without it.
     * The largest definite weight on this level is t C_compl. S depends on
     * the weight only through M_CC, since the complementarity term couples
     * only the contact normal DoFs, so that S(t) is affine in t and the
     * limit is 1 / (the largest eigenvalue of -M_CC x = mu S_0 x), a dense
     * generalized eigenproblem of the size of S. +inf where no weight
     * makes S indefinite; NaN where S_0 itself is not positive definite
     * (then no weight helps: the cause lies elsewhere).
     */
    double limit_factor = std::numeric_limits<double>::infinity();
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
