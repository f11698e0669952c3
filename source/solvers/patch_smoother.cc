#include <fosls_contact/solvers/patch_smoother.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  PatchSmoother::PatchSmoother(const unsigned int n_levels)
    : MGSmoother<Vector<double>>(1)
    , levels(n_levels)
  {}


  void
  PatchSmoother::initialize_level(
    const unsigned int                                       l,
    const SparseMatrix<double> &                             matrix,
    const std::vector<std::vector<types::global_dof_index>> &patches,
    const std::vector<DoFRole> &                             role)
  {
    Level &level = levels[l];
    level = Level();
    level.start.push_back(0);
    level.inverse_start.push_back(0);
    level.row_start.push_back(0);
    std::vector<types::global_dof_index> dofs;
    for (const auto &all_dofs : patches)
      {
        dofs.clear();
        bool any_bounded = false;
        for (const auto dof : all_dofs)
          if (role[dof] != DoFRole::fixed && matrix.diag_element(dof) > 0)
            {
              dofs.push_back(dof);
              any_bounded |= role[dof] == DoFRole::bounded;
            }
        if (dofs.empty())
          continue;
        const unsigned int n = dofs.size();
        FullMatrix<double> M(n, n);
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            M(a, b) = matrix.el(dofs[a], dofs[b]);
        BoxQP qp(M);
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            level.inverse.push_back(qp.inverse_entry(a, b));
        for (const auto dof : dofs)
          {
            level.dofs.push_back(dof);
            level.bounded.push_back(role[dof] == DoFRole::bounded);
            for (auto e = matrix.begin(dof); e != matrix.end(dof); ++e)
              if (e->value() != 0.)
                {
                  level.columns.push_back(e->column());
                  level.values.push_back(e->value());
                }
            level.row_start.push_back(level.values.size());
          }
        level.box_qp.push_back(any_bounded ? level.qps.size() :
                                             numbers::invalid_unsigned_int);
        if (any_bounded)
          level.qps.push_back(std::move(qp));
        level.start.push_back(level.dofs.size());
        level.inverse_start.push_back(level.inverse.size());
      }
  }


  void
  PatchSmoother::set_obstacles(const unsigned int l, const Vector<double> &ub)
  {
    levels[l].obstacles = &ub;
  }


  void
  PatchSmoother::smooth(const unsigned int    l,
                        Vector<double> &      v,
                        const Vector<double> &r) const
  {
    const Level &level = levels[l];
    const auto & ub    = *level.obstacles;
    const double inf   = std::numeric_limits<double>::infinity();
    std::vector<double> g, s, c;
    std::vector<bool>   at_bound;

    const unsigned int n_patches = level.box_qp.size();
    for (unsigned int step = 0; step < steps; ++step)
      for (unsigned int kk = 0; kk < n_patches; ++kk)
        {
          const unsigned int k     = backward ? n_patches - 1 - kk : kk;
          const auto *       dofs  = level.dofs.data() + level.start[k];
          const unsigned int n     = level.start[k + 1] - level.start[k];
          const double *     inv   = level.inverse.data() + level.inverse_start[k];
          g.resize(n);
          s.resize(n);
          c.resize(n);
          for (unsigned int a = 0; a < n; ++a)
            {
              const auto         i     = dofs[a];
              const std::size_t  first = level.row_start[level.start[k] + a];
              const std::size_t  last  = level.row_start[level.start[k] + a + 1];
              const unsigned int *column = level.columns.data();
              const double *      value  = level.values.data();
              double              gi     = r[i];
              for (std::size_t e = first; e < last; ++e)
                gi -= value[e] * v[column[e]];
              g[a] = gi;
              s[a] = level.bounded[level.start[k] + a] ? std::max(0., ub[i] - v[i]) : inf;
            }
          // the unconstrained patch minimizer c = M^{-1} g, and the change
          // of the objective, 1/2 c^T M c - g^T c = -1/2 g^T c
          bool   feasible = true;
          double gc       = 0;
          for (unsigned int a = 0; a < n; ++a)
            {
              double ca = 0;
              for (unsigned int b = 0; b < n; ++b)
                ca += inv[a * n + b] * g[b];
              c[a] = ca;
              gc += g[a] * ca;
              feasible &= ca <= s[a];
            }
          double change = -0.5 * gc;
          if (feasible)
            at_bound.assign(n, false);
          else
            change = level.qps[level.box_qp[k]].solve(g.data(), s.data(), c.data(), at_bound);
          double scale = 0;
          for (unsigned int a = 0; a < n; ++a)
            {
              const auto i = dofs[a];
              v[i] = at_bound[a] ? ub[i] : v[i] + c[a];
              scale += std::abs(g[a] * c[a]);
            }
          // exact minimization on the patch: the change is <= 0 up to
          // round-off relative to its own terms
          if (change > 1e-10 * scale + 1e-300)
            ++n_increases;
        }
  }


  void
  PatchSmoother::clear()
  {
    for (auto &level : levels)
      level = Level();
  }
} // namespace FoslsContact
