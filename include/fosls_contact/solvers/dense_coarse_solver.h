#ifndef fosls_contact_solvers_dense_coarse_solver_h
#define fosls_contact_solvers_dense_coarse_solver_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/solvers/box_qp.h>

#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The exact solve of a small coarsest level (at most a few thousand DoFs that
   * move), minimize 1/2 c^T M c - g^T c subject to c_i <= s_i, for one matrix M
   * and many right-hand sides: a W-cycle visits the coarsest level hundreds of
   * times per operator, so a factorization per visit would cost more than the
   * rest of the cycle (doc/performance.md, "Figures behind the code").
   *
   * A visit without a finite bound (every visit of the Newton step's
   * linear cycle) solves M c = g with the Cholesky factor of M; one with a
   * finite bound uses a BoxQP (the inverse and an active set method). Each
   * is made when first needed for the current matrix: the factor is
   * several times cheaper to make than the inverse, and a linear visit
   * costs about the same with either (two triangular solves against one
   * product with the inverse; doc/performance.md, "Figures behind the code").
   * M is positive definite in exact arithmetic, but should LAPACK refuse
   * the factor (a pivot <= 0 in floating point), the linear visits go to
   * the BoxQP, whose Gauss-Jordan inverse pivots.
   */
  class DenseCoarseSolver
  {
  public:
    /** The factorization's state for the current matrix. */
    enum class Cholesky : unsigned char
    {
      none,
      factorized,
      refused
    };

    /**
     * A new matrix: the factorizations of the old one are dropped (made
     * again when needed).
     */
    void reinit(const FullMatrix<double> &M);

    /**
     * The exact minimizer @p c for @p g and the bounds @p s (s_i >= 0,
     * +inf where unbounded); at_bound[i] tells whether c_i = s_i.
     */
    void solve(const Vector<double> &g,
               const Vector<double> &s,
               Vector<double> &      c,
               std::vector<bool> &   at_bound);

    Cholesky cholesky_state() const { return state; }

  private:
    FullMatrix<double>       matrix;
    LAPACKFullMatrix<double> cholesky;
    Cholesky                 state = Cholesky::none;
    BoxQP                    box_qp;
    bool                     box_qp_ready = false;
  };
} // namespace FoslsContact

#endif
