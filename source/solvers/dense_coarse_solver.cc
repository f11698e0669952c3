#include <fosls_contact/solvers/dense_coarse_solver.h>

#include <algorithm>
#include <limits>

namespace FoslsContact
{
  void
  DenseCoarseSolver::reinit(const FullMatrix<double> &M)
  {
    matrix       = M;
    state        = Cholesky::none;
    box_qp_ready = false;
  }


  void
  DenseCoarseSolver::solve(const Vector<double> &g,
                           const Vector<double> &s,
                           Vector<double> &      c,
                           std::vector<bool> &   at_bound)
  {
    AssertDimension(g.size(), matrix.m());
    AssertDimension(s.size(), matrix.m());
    AssertDimension(c.size(), matrix.m());
    const bool linear = std::all_of(s.begin(), s.end(), [](const double bound) {
      return bound == std::numeric_limits<double>::infinity();
    });
    if (linear && state == Cholesky::none)
      {
        cholesky.reinit(matrix.m());
        cholesky = matrix;
        cholesky.set_property(LAPACKSupport::symmetric);
        try
          {
            cholesky.compute_cholesky_factorization();
            state = Cholesky::factorized;
          }
        catch (const ExceptionBase &)
          {
            state = Cholesky::refused;
          }
      }
    if (linear && state == Cholesky::factorized)
      {
        c = g;
        cholesky.solve(c);
        at_bound.assign(matrix.m(), false);
        return;
      }
    if (!box_qp_ready)
      {
        box_qp       = BoxQP(matrix);
        box_qp_ready = true;
      }
    // (the pointer version: where no bound is reached, one product with
    // the inverse, without the objective's second product, which is not
    // needed here)
    box_qp.solve(g.begin(), s.begin(), c.begin(), at_bound);
  }
} // namespace FoslsContact
