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
    level.matrix = &matrix;
    level.patches.clear();
    level.patches.reserve(patches.size());
    for (const auto &all_dofs : patches)
      {
        Patch patch;
        for (const auto dof : all_dofs)
          if (role[dof] != DoFRole::fixed && matrix.diag_element(dof) > 0)
            {
              patch.dofs.push_back(dof);
              patch.bounded.push_back(role[dof] == DoFRole::bounded);
            }
        if (patch.dofs.empty())
          continue;
        const unsigned int n = patch.dofs.size();
        FullMatrix<double> M(n, n);
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            M(a, b) = matrix.el(patch.dofs[a], patch.dofs[b]);
        patch.qp = BoxQP(M);
        level.patches.push_back(std::move(patch));
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
    const auto & A     = *level.matrix;
    const auto & ub    = *level.obstacles;
    const double inf   = std::numeric_limits<double>::infinity();
    std::vector<double> g, s, c;
    std::vector<bool>   at_bound;

    const unsigned int n_patches = level.patches.size();
    for (unsigned int step = 0; step < steps; ++step)
      for (unsigned int k = 0; k < n_patches; ++k)
        {
          const Patch &      patch = level.patches[backward ? n_patches - 1 - k : k];
          const unsigned int n     = patch.dofs.size();
          g.resize(n);
          s.resize(n);
          c.resize(n);
          double scale = 0;
          for (unsigned int a = 0; a < n; ++a)
            {
              const auto i  = patch.dofs[a];
              double     gi = r[i];
              for (auto e = A.begin(i); e != A.end(i); ++e)
                gi -= e->value() * v[e->column()];
              g[a] = gi;
              s[a] = patch.bounded[a] ? std::max(0., ub[i] - v[i]) : inf;
            }
          const double change = patch.qp.solve(g.data(), s.data(), c.data(), at_bound);
          for (unsigned int a = 0; a < n; ++a)
            {
              const auto i = patch.dofs[a];
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
