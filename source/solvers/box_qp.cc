#include <fosls_contact/solvers/box_qp.h>
#include <fosls_contact/solvers/spd_inverse.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  BoxQP::BoxQP(const FullMatrix<double> &M)
    : matrix(M)
  {
    inverse = M;
    invert_spd(inverse);
  }


  double
  BoxQP::solve(const double *g,
               const double *s,
               double *      c,
               std::vector<bool> &at_bound) const
  {
    const unsigned int n        = matrix.m();
    bool               feasible = true;
    double             gc       = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        double ci = 0;
        for (unsigned int j = 0; j < n; ++j)
          ci += inverse(i, j) * g[j];
        c[i] = ci;
        gc += g[i] * ci;
        feasible &= ci <= s[i];
      }
    if (feasible)
      {
        at_bound.assign(n, false);
        return -0.5 * gc; // 1/2 c^T M c - g^T c with M c = g
      }
    Vector<double> gv(g, g + n), sv(s, s + n), cv;
    const double   change = solve(gv, sv, cv, at_bound);
    for (unsigned int i = 0; i < n; ++i)
      c[i] = cv[i];
    return change;
  }


  double
  BoxQP::solve(const Vector<double> &g,
               const Vector<double> &s,
               Vector<double> &      c,
               std::vector<bool> &   at_bound) const
  {
    const unsigned int n = matrix.m();
    c.reinit(n);
    at_bound.assign(n, false);
    auto objective = [&](const Vector<double> &v) {
      return 0.5 * matrix.matrix_norm_square(v) - g * v;
    };

    // unconstrained minimizer
    Vector<double> trial(n);
    inverse.vmult(trial, g);
    bool feasible = true;
    for (unsigned int i = 0; i < n; ++i)
      feasible &= trial[i] <= s[i];
    if (feasible)
      {
        c = trial;
        return objective(c);
      }

    // primal active set from the feasible point c = 0
    std::vector<bool> working(n, false);
    Vector<double>    Mc(n);
    for (unsigned int step = 0; step < 10 * n + 10; ++step)
      {
        // equality-constrained minimizer with c_W = s_W
        std::vector<unsigned int> free;
        for (unsigned int i = 0; i < n; ++i)
          if (!working[i])
            free.push_back(i);
        trial = 0;
        for (unsigned int i = 0; i < n; ++i)
          if (working[i])
            trial[i] = s[i];
        if (!free.empty())
          {
            FullMatrix<double> M_ff(free.size(), free.size());
            Vector<double>     rhs(free.size()), sol(free.size());
            for (unsigned int a = 0; a < free.size(); ++a)
              {
                rhs[a] = g[free[a]];
                for (unsigned int i = 0; i < n; ++i)
                  if (working[i])
                    rhs[a] -= matrix(free[a], i) * s[i];
                for (unsigned int b = 0; b < free.size(); ++b)
                  M_ff(a, b) = matrix(free[a], free[b]);
              }
            invert_spd(M_ff);
            M_ff.vmult(sol, rhs);
            for (unsigned int a = 0; a < free.size(); ++a)
              trial[free[a]] = sol[a];
          }

        // step from c toward trial, stopping at the first blocking bound
        double       t        = 1.;
        unsigned int blocking = numbers::invalid_unsigned_int;
        for (unsigned int i = 0; i < n; ++i)
          if (!working[i] && trial[i] > s[i])
            {
              const double ti = (s[i] - c[i]) / (trial[i] - c[i]);
              if (ti < t)
                {
                  t        = ti;
                  blocking = i;
                }
            }
        if (blocking != numbers::invalid_unsigned_int)
          {
            for (unsigned int i = 0; i < n; ++i)
              c[i] += t * (trial[i] - c[i]);
            working[blocking] = true;
            c[blocking]       = s[blocking];
            continue;
          }
        c = trial;

        // multipliers of the working set: mu = g - M c >= 0
        matrix.vmult(Mc, c);
        double       most_negative = 0;
        unsigned int drop          = numbers::invalid_unsigned_int;
        for (unsigned int i = 0; i < n; ++i)
          if (working[i])
            {
              const double mu = g[i] - Mc[i];
              if (mu < most_negative)
                {
                  most_negative = mu;
                  drop          = i;
                }
            }
        if (drop == numbers::invalid_unsigned_int ||
            most_negative > -1e-14 * (std::abs(g[drop]) + std::abs(Mc[drop])))
          break;
        working[drop] = false;
      }
    for (unsigned int i = 0; i < n; ++i)
      if (working[i])
        {
          c[i]        = s[i];
          at_bound[i] = true;
        }
    return objective(c);
  }
} // namespace FoslsContact
