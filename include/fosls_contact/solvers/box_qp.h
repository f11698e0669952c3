#ifndef fosls_contact_solvers_box_qp_h
#define fosls_contact_solvers_box_qp_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Exact solution of a small dense box-constrained quadratic problem
   *
   *   minimize 1/2 c^T M c - g^T c   subject to c_i <= s_i,
   *
   * with M symmetric positive definite and s_i >= 0 (so c = 0 is feasible;
   * s_i = +inf for unbounded entries). This is the local problem of one
   * vertex patch (paper eq. 24) and of a small coarsest level.
   *
   * A primal active set method: starting from c = 0, it solves the
   * equality-constrained problem on the working set, steps to the first
   * blocking bound, and drops the bound with the most negative multiplier;
   * every step decreases the objective, so it terminates after finitely
   * many steps at the exact minimizer. The common case of no bound reached
   * costs one product with the precomputed inverse.
   */
  class BoxQP
  {
  public:
    BoxQP() = default;
    /** Store M and its inverse (M must be symmetric positive definite). */
    explicit BoxQP(const FullMatrix<double> &M);

    unsigned int size() const { return matrix.m(); }

    /** Entry (i, j) of M. */
    double matrix_entry(const unsigned int i, const unsigned int j) const
    {
      return matrix(i, j);
    }

    /** The inverse of M. */
    const FullMatrix<double> &inverse_matrix() const { return inverse; }

    /** The bytes of M and its inverse. */
    std::size_t memory_consumption() const
    {
      return sizeof(*this) + matrix.memory_consumption() + inverse.memory_consumption();
    }

    /**
     * Solve; on return, c is the minimizer and at_bound[i] tells whether
     * c_i = s_i (then c_i is set to s_i exactly). Returns the change of
     * the objective, 1/2 c^T M c - g^T c (never positive up to round-off).
     */
    double solve(const Vector<double> &   g,
                 const Vector<double> &   s,
                 Vector<double> &         c,
                 std::vector<bool> &      at_bound) const;

    /**
     * The same on raw arrays of size(), without allocations when no bound
     * is reached (the hot path of the smoother).
     */
    double solve(const double *       g,
                 const double *       s,
                 double *             c,
                 std::vector<bool> &  at_bound) const;

    /** Where an entry of the solution of solve_with_friction() ends. */
    enum class Bound : unsigned char
    {
      none,  ///< strictly between its bounds and off its kink
      lower, ///< c_i = lo_i
      upper, ///< c_i = hi_i
      kink,  ///< c_i = q_i
    };

    /**
     * The local problem of a patch with friction DoFs:
     *
     *   minimize 1/2 c^T M c - g^T c + sum_i w_i |c_i - q_i|
     *   subject to lo_i <= c_i <= hi_i,
     *
     * with lo_i <= 0 <= hi_i (c = 0 is feasible; +-inf for no bound; an
     * entry with lo_i = hi_i = 0 is held at 0) and w_i >= 0 (0: no kink).
     * The same primal active set method as solve(): a kink is a
     * constraint c_i = q_i in the working set, and an entry
     * off its kink carries the slope w_i of its side; an entry leaves the
     * working set when its multiplier mu_i = (g - M c)_i points out of it
     * (at a kink: |mu_i| > w_i, to the side of mu_i). J decreases in every
     * step, so the method ends at the exact minimizer. On return
     * @p where[i] tells which bound or kink c_i is on (then it is set to
     * it exactly). Returns the change of the objective against c = 0.
     * @p from_inverse: solve the reduced problems of a working set of at
     * most max_held_from_inverse entries by a Schur complement of the
     * stored inverse, in O(n^2), instead of factorizing M on the free
     * entries (3D friction solves each patch several times with its pairs
     * held, PatchSmoother).
     */
    double solve_with_friction(const double *      g,
                               const double *      lo,
                               const double *      hi,
                               const double *      q,
                               const double *      w,
                               double *            c,
                               std::vector<Bound> &where,
                               const bool          from_inverse = false) const;

    /** The largest working set solve_with_friction() takes from the inverse. */
    static constexpr unsigned int max_held_from_inverse = 24;

  private:
    /**
     * The solution @p sol of M_FF sol = @p rhs on the entries @p free (with
     * the stored inverse where they are all of them).
     */
    void solve_reduced(const std::vector<unsigned int> &free,
                       const Vector<double> &           rhs,
                       Vector<double> &                 sol,
                       const bool                       from_inverse = false) const;

    FullMatrix<double> matrix;
    FullMatrix<double> inverse;
  };
} // namespace FoslsContact

#endif
