// Checks DenseCoarseSolver, the exact solve of the coarsest level:
//  - without finite bounds it solves M c = g with the Cholesky factor, made
//    once per matrix;
//  - with finite bounds, the BoxQP's result satisfies the KKT conditions
//    (c <= s, g - M c = 0 where c_i < s_i and >= 0 where c_i = s_i);
//  - a matrix whose Cholesky factor LAPACK refuses goes to the BoxQP's
//    Gauss-Jordan inverse, and M c = g still holds. (The coarse operators
//    are positive definite in exact arithmetic, and no scene makes LAPACK
//    refuse one; a symmetric indefinite matrix stands in for that case
//    here: every pivot of dpotrf after the first is <= 0.)
//  - reinit() with a new matrix drops the old factorizations.
#include <fosls_contact/solvers/dense_coarse_solver.h>

#include "tests.h"

#include <limits>

using namespace FoslsContactTests;

namespace
{
  /** max_i |(M c - g)_i| / max_i |g_i| */
  double
  relative_residual(const FullMatrix<double> &M, const Vector<double> &c, const Vector<double> &g)
  {
    Vector<double> Mc(c.size());
    M.vmult(Mc, c);
    Mc -= g;
    return Mc.linfty_norm() / g.linfty_norm();
  }


  /** A 1D Laplacian-like matrix plus @p shift times the identity. */
  FullMatrix<double>
  laplacian(const unsigned int n, const double shift)
  {
    FullMatrix<double> M(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        M(i, i) = 2. + shift;
        if (i + 1 < n)
          M(i, i + 1) = M(i + 1, i) = -1.;
      }
    return M;
  }


  Vector<double>
  load(const unsigned int n)
  {
    Vector<double> g(n);
    for (unsigned int i = 0; i < n; ++i)
      g[i] = 1. + 0.25 * std::sin(1. + i);
    return g;
  }
} // namespace


int
main()
{
  const double       inf = std::numeric_limits<double>::infinity();
  const unsigned int n   = 12;
  DenseCoarseSolver  solver;
  std::vector<bool>  at_bound;
  Vector<double>     c(n), unbounded(n);
  unbounded = inf;
  const Vector<double> g = load(n);

  // positive definite, no finite bound: Cholesky
  const FullMatrix<double> M = laplacian(n, 0.1);
  solver.reinit(M);
  check(solver.cholesky_state() == DenseCoarseSolver::Cholesky::none,
        "no factor before the first solve");
  solver.solve(g, unbounded, c, at_bound);
  check(solver.cholesky_state() == DenseCoarseSolver::Cholesky::factorized,
        "positive definite, no bound: the Cholesky factor is made");
  check(relative_residual(M, c, g) < 1e-13, "M c = g");
  check(std::none_of(at_bound.begin(), at_bound.end(), [](const bool b) { return b; }),
        "no DoF at a bound");

  // finite bounds on every other DoF: the BoxQP, checked by its KKT
  // conditions (the unconstrained solution exceeds 0.5 at every DoF, so
  // the bounds 0.5 are reached)
  Vector<double> s = unbounded;
  for (unsigned int i = 0; i < n; i += 2)
    s[i] = 0.5;
  solver.solve(g, s, c, at_bound);
  Vector<double> multiplier(n); // g - M c
  M.vmult(multiplier, c);
  multiplier.sadd(-1., 1., g);
  bool         feasible = true, kkt = true;
  unsigned int n_at_bound = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      feasible &= c[i] <= s[i];
      if (at_bound[i])
        {
          ++n_at_bound;
          kkt &= c[i] == s[i] && multiplier[i] >= -1e-13;
        }
      else
        kkt &= std::abs(multiplier[i]) <= 1e-13 * g.linfty_norm();
    }
  std::cout << "DoFs at their bound: " << n_at_bound << std::endl;
  check(n_at_bound > 0, "finite bounds: some are reached");
  check(feasible && kkt, "finite bounds: c <= s and the KKT conditions hold");

  // a factor LAPACK refuses: the linear visits go to the BoxQP
  FullMatrix<double> indefinite(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      indefinite(i, j) = (i == j) ? 1. : (i + 1 == j || j + 1 == i) ? 2. : 0.;
  solver.reinit(indefinite);
  check(solver.cholesky_state() == DenseCoarseSolver::Cholesky::none,
        "reinit drops the old factor");
  solver.solve(g, unbounded, c, at_bound);
  check(solver.cholesky_state() == DenseCoarseSolver::Cholesky::refused,
        "indefinite: LAPACK refuses the Cholesky factor");
  check(relative_residual(indefinite, c, g) < 1e-12, "fallback to the BoxQP: M c = g");
  check(std::none_of(at_bound.begin(), at_bound.end(), [](const bool b) { return b; }),
        "fallback: no DoF at a bound");
  // a second linear solve keeps the refusal (no new attempt) and the
  // same answer
  Vector<double> c2(n);
  solver.solve(g, unbounded, c2, at_bound);
  c2 -= c;
  check(solver.cholesky_state() == DenseCoarseSolver::Cholesky::refused && c2.linfty_norm() == 0.,
        "fallback: a second solve gives the same bits");

  // a positive definite matrix again: the factor is made for it
  solver.reinit(laplacian(n, 1.));
  solver.solve(g, unbounded, c, at_bound);
  check(solver.cholesky_state() == DenseCoarseSolver::Cholesky::factorized &&
          relative_residual(laplacian(n, 1.), c, g) < 1e-13,
        "a new positive definite matrix: factorized, M c = g");
  return exit_code();
}
