#include <fosls_contact/solvers/box_qp.h>
#include <fosls_contact/solvers/spd_inverse.h>

#include <algorithm>
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
            Vector<double> rhs(free.size()), sol;
            for (unsigned int a = 0; a < free.size(); ++a)
              {
                rhs[a] = g[free[a]];
                for (unsigned int i = 0; i < n; ++i)
                  if (working[i])
                    rhs[a] -= matrix(free[a], i) * s[i];
              }
            solve_reduced(free, rhs, sol);
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


  void
  BoxQP::solve_reduced(const std::vector<unsigned int> &free,
                       const Vector<double> &           rhs,
                       Vector<double> &                 sol,
                       const bool                       from_inverse) const
  {
    sol.reinit(free.size());
    if (free.empty())
      return;
    if (free.size() == matrix.m())
      {
        inverse.vmult(sol, rhs);
        return;
      }
    const unsigned int n = matrix.m(), n_held = n - free.size();
    if (from_inverse && n_held <= max_held_from_inverse)
      {
        // M_FF^{-1} = G_FF - G_FH G_HH^{-1} G_HF with G = M^{-1} and H the
        // held entries: O(n^2) instead of a new factorization
        std::vector<unsigned int> held;
        std::vector<bool>         is_free(n, false);
        for (const unsigned int i : free)
          is_free[i] = true;
        for (unsigned int i = 0; i < n; ++i)
          if (!is_free[i])
            held.push_back(i);
        FullMatrix<double> G_hh(n_held, n_held);
        Vector<double>     t(n_held), u(n_held);
        for (unsigned int a = 0; a < n_held; ++a)
          {
            for (unsigned int b = 0; b < n_held; ++b)
              G_hh(a, b) = inverse(held[a], held[b]);
            double ta = 0;
            for (unsigned int c = 0; c < free.size(); ++c)
              ta += inverse(held[a], free[c]) * rhs[c];
            t[a] = ta;
          }
        invert_spd(G_hh);
        G_hh.vmult(u, t);
        for (unsigned int c = 0; c < free.size(); ++c)
          {
            double value = 0;
            for (unsigned int e = 0; e < free.size(); ++e)
              value += inverse(free[c], free[e]) * rhs[e];
            for (unsigned int a = 0; a < n_held; ++a)
              value -= inverse(free[c], held[a]) * u[a];
            sol[c] = value;
          }
        return;
      }
    FullMatrix<double> M_ff(free.size(), free.size());
    for (unsigned int a = 0; a < free.size(); ++a)
      for (unsigned int b = 0; b < free.size(); ++b)
        M_ff(a, b) = matrix(free[a], free[b]);
    invert_spd(M_ff);
    M_ff.vmult(sol, rhs);
  }


  double
  BoxQP::solve_with_friction(const double *      g,
                             const double *      lo,
                             const double *      hi,
                             const double *      q,
                             const double *      w,
                             double *            c,
                             std::vector<Bound> &where,
                             const bool          from_inverse) const
  {
    const unsigned int n = matrix.m();
    where.assign(n, Bound::none);
    // the side of its kink an entry off it is on (the sign of c_i - q_i,
    // kept explicitly: an entry released from its kink is still on it)
    std::vector<double> side(n, 0.);
    for (unsigned int i = 0; i < n; ++i)
      {
        c[i] = 0;
        // (an entry with lo_i = hi_i = 0 is held there throughout)
        if (lo[i] == hi[i])
          where[i] = Bound::upper;
        else if (w[i] > 0)
          {
            if (q[i] == 0)
              where[i] = Bound::kink;
            else
              side[i] = q[i] < 0 ? 1. : -1.;
          }
      }
    const auto value = [&](const unsigned int i) {
      return where[i] == Bound::lower ? lo[i] : where[i] == Bound::upper ? hi[i] : q[i];
    };

    std::vector<unsigned int> free;
    Vector<double>            rhs, sol;
    std::vector<double>       trial(n), Mc(n);
    for (unsigned int step = 0; step < 10 * n + 10; ++step)
      {
        // the minimizer with the working set at its values and the slopes
        // of the free entries' sides
        free.clear();
        for (unsigned int i = 0; i < n; ++i)
          if (where[i] == Bound::none)
            free.push_back(i);
        for (unsigned int i = 0; i < n; ++i)
          trial[i] = where[i] == Bound::none ? 0. : value(i);
        rhs.reinit(free.size());
        for (unsigned int a = 0; a < free.size(); ++a)
          {
            const unsigned int i = free[a];
            rhs[a]               = g[i] - side[i] * w[i];
            for (unsigned int j = 0; j < n; ++j)
              if (where[j] != Bound::none)
                rhs[a] -= matrix(i, j) * trial[j];
          }
        solve_reduced(free, rhs, sol, from_inverse);
        for (unsigned int a = 0; a < free.size(); ++a)
          trial[free[a]] = sol[a];

        // step from c toward trial, stopping at the first bound or kink
        double       t        = 1.;
        unsigned int blocking = numbers::invalid_unsigned_int;
        Bound        blocked  = Bound::none;
        const auto   block    = [&](const unsigned int i, const double target, const Bound b) {
          const double ti = std::max(0., (target - c[i]) / (trial[i] - c[i]));
          if (ti < t)
            {
              t        = ti;
              blocking = i;
              blocked  = b;
            }
        };
        for (const unsigned int i : free)
          {
            if (trial[i] > hi[i])
              block(i, hi[i], Bound::upper);
            if (trial[i] < lo[i])
              block(i, lo[i], Bound::lower);
            if ((side[i] > 0 && trial[i] < q[i]) || (side[i] < 0 && trial[i] > q[i]))
              block(i, q[i], Bound::kink);
          }
        if (blocking != numbers::invalid_unsigned_int)
          {
            for (unsigned int i = 0; i < n; ++i)
              c[i] += t * (trial[i] - c[i]);
            where[blocking] = blocked;
            c[blocking]     = value(blocking);
            continue;
          }
        std::copy(trial.begin(), trial.end(), c);

        // the multipliers of the working set, mu = g - M c: the entry that
        // points out of its bound or kink the most leaves it
        double       most   = 0;
        unsigned int leaves = numbers::invalid_unsigned_int;
        for (unsigned int i = 0; i < n; ++i)
          if (where[i] != Bound::none && lo[i] != hi[i])
            {
              double mci = 0;
              for (unsigned int j = 0; j < n; ++j)
                mci += matrix(i, j) * c[j];
              const double mu        = g[i] - mci;
              const double violation = where[i] == Bound::upper ? -mu :
                                       where[i] == Bound::lower ? mu :
                                                                  std::abs(mu) - w[i];
              if (violation > most &&
                  violation > 1e-14 * (std::abs(g[i]) + std::abs(mci) + w[i]))
                {
                  most   = violation;
                  leaves = i;
                  Mc[i]  = mu;
                }
            }
        if (leaves == numbers::invalid_unsigned_int)
          break;
        if (where[leaves] == Bound::kink)
          side[leaves] = Mc[leaves] > 0 ? 1. : -1.;
        where[leaves] = Bound::none;
      }
    double objective = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        if (where[i] != Bound::none)
          c[i] = value(i);
        double mci = 0;
        for (unsigned int j = 0; j < n; ++j)
          mci += matrix(i, j) * c[j];
        objective += 0.5 * c[i] * mci - g[i] * c[i] + w[i] * (std::abs(c[i] - q[i]) - std::abs(q[i]));
      }
    return objective;
  }
} // namespace FoslsContact
