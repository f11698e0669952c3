// Checks BoxQP::solve_with_friction(), the local problem of a vertex patch
// with friction DoFs: minimize 1/2 c^T M c - g^T c + sum_i w_i |c_i - q_i|
// subject to lo_i <= c_i <= hi_i, on 200 pseudo-random problems of 12
// entries (a random SPD M, entries in turn an obstacle (hi only), a
// traction (lo and hi), a kink and free):
//  - the result is feasible, on its reported bound or kink exactly;
//  - it satisfies the optimality conditions with mu = g - M c: mu_i = 0 on
//    a free entry, mu_i = w_i sgn(c_i - q_i) off a kink, |mu_i| <= w_i on
//    it, mu_i >= 0 at an upper bound and <= 0 at a lower one (to 1e-9 of
//    the size of the terms);
//  - the returned change is the objective at c less that at 0, and <= 0;
//  - no coordinate step of 1e-6 (either direction, kept feasible) lowers
//    the objective: c is a local, hence the global, minimizer.
// ctest: sanitize
#include <deal.II/lac/full_matrix.h>

#include <fosls_contact/solvers/box_qp.h>

#include "tests.h"

#include <cmath>
#include <limits>
#include <random>

using namespace FoslsContactTests;

int
main()
{
  const unsigned int               n = 12, n_problems = 200;
  const double                     infinity = std::numeric_limits<double>::infinity();
  std::mt19937                     random(42);
  std::uniform_real_distribution<> uniform(-1., 1.);
  unsigned int n_feasible = 0, n_kkt = 0, n_change = 0, n_local = 0;
  unsigned int on_kink = 0, on_bound = 0;
  for (unsigned int problem = 0; problem < n_problems; ++problem)
    {
      FullMatrix<double> B(n, n), M(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          B(i, j) = uniform(random);
      B.Tmmult(M, B);
      for (unsigned int i = 0; i < n; ++i)
        M(i, i) += 0.1;
      std::vector<double> g(n), lo(n, -infinity), hi(n, infinity), q(n, 0.), w(n, 0.), c(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          g[i] = 3 * uniform(random);
          switch (i % 4)
            {
              case 0: // an obstacle, sometimes reached at the start
                hi[i] = problem % 3 == 0 ? 0. : 0.5 * (1 + uniform(random));
                break;
              case 1: // a traction between +-s, sometimes at one end
                lo[i] = -0.5 * (1 + uniform(random));
                hi[i] = problem % 5 == 0 ? 0. : 0.5 * (1 + uniform(random));
                break;
              case 2: // a kink, sometimes at the start
                q[i] = problem % 4 == 0 ? 0. : uniform(random);
                w[i] = 1 + uniform(random);
                break;
              default:
                break;
            }
        }
      const BoxQP                qp(M);
      std::vector<BoxQP::Bound>  where;
      const double change = qp.solve_with_friction(
        g.data(), lo.data(), hi.data(), q.data(), w.data(), c.data(), where);

      const auto objective = [&](const std::vector<double> &x) {
        double value = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            double mx = 0;
            for (unsigned int j = 0; j < n; ++j)
              mx += M(i, j) * x[j];
            value += 0.5 * x[i] * mx - g[i] * x[i] + w[i] * std::abs(x[i] - q[i]);
          }
        return value;
      };
      const std::vector<double> zero(n, 0.);

      bool feasible = true, kkt = true;
      for (unsigned int i = 0; i < n; ++i)
        {
          feasible &= lo[i] <= c[i] && c[i] <= hi[i];
          feasible &= where[i] != BoxQP::Bound::lower || c[i] == lo[i];
          feasible &= where[i] != BoxQP::Bound::upper || c[i] == hi[i];
          feasible &= where[i] != BoxQP::Bound::kink || c[i] == q[i];
          on_kink += where[i] == BoxQP::Bound::kink;
          on_bound += where[i] == BoxQP::Bound::lower || where[i] == BoxQP::Bound::upper;
          double mc = 0, size = std::abs(g[i]) + w[i];
          for (unsigned int j = 0; j < n; ++j)
            {
              mc += M(i, j) * c[j];
              size += std::abs(M(i, j) * c[j]);
            }
          const double mu = g[i] - mc, tolerance = 1e-9 * size;
          switch (where[i])
            {
              case BoxQP::Bound::none:
                kkt &= std::abs(mu - (w[i] > 0 ? w[i] * (c[i] > q[i] ? 1 : -1) : 0.)) <= tolerance;
                break;
              case BoxQP::Bound::kink:
                kkt &= std::abs(mu) <= w[i] + tolerance;
                break;
              case BoxQP::Bound::upper:
                kkt &= mu >= -tolerance;
                break;
              case BoxQP::Bound::lower:
                kkt &= mu <= tolerance;
                break;
            }
        }
      n_feasible += feasible;
      n_kkt += kkt;
      const double expected = objective(c) - objective(zero);
      n_change += change <= 1e-12 && std::abs(change - expected) <= 1e-10 * (1 + std::abs(expected));

      bool local = true;
      for (unsigned int i = 0; i < n; ++i)
        for (const double step : {-1e-6, 1e-6})
          {
            std::vector<double> x = c;
            x[i] = std::max(lo[i], std::min(hi[i], x[i] + step));
            local &= objective(x) >= objective(c) - 1e-13;
          }
      n_local += local;
    }
  std::cout << n_problems << " problems: " << on_bound << " entries end on a bound, " << on_kink
            << " on a kink" << std::endl;
  check(n_feasible == n_problems, "every result feasible, on its bound or kink exactly");
  check(n_kkt == n_problems, "every result satisfies the optimality conditions (to 1e-9)");
  check(n_change == n_problems, "the returned change is the objective's, and <= 0");
  check(n_local == n_problems, "no feasible coordinate step of 1e-6 lowers the objective");
  return exit_code();
}
