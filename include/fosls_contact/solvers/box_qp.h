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

  private:
    FullMatrix<double> matrix;
    FullMatrix<double> inverse;
  };
} // namespace FoslsContact

#endif
