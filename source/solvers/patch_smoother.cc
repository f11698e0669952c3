#include <fosls_contact/solvers/patch_smoother.h>

#include <deal.II/base/parallel.h>
#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  PatchSmoother::PatchSmoother(const unsigned int n_levels)
    : MGSmoother<LevelVector>(1)
    , levels(n_levels)
  {}


  void
  PatchSmoother::initialize_level(
    const unsigned int                                       l,
    const SparseMatrix<double> &                             matrix,
    const std::vector<std::vector<types::global_dof_index>> &patches,
    const std::vector<unsigned int> &                        patch_color,
    const unsigned int                                       n_colors,
    const std::vector<DoFRole> &                             role,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
  {
    Level &level = levels[l];
    level        = Level();
    const unsigned int n_owned = partitioner->locally_owned_size();

    // Layout (serial): the patches in color order, each with the DoFs that
    // can move (not fixed, not switched off by a zero diagonal), its
    // neighbourhood (those DoFs first, then the other columns of their
    // rows) and its rows with columns numbered within the neighbourhood.
    std::vector<std::vector<unsigned int>> by_color(n_colors);
    for (unsigned int p = 0; p < patches.size(); ++p)
      by_color[patch_color[p]].push_back(p);
    level.start.push_back(0);
    level.inverse_start.push_back(0);
    level.neighbor_start.push_back(0);
    level.row_start.push_back(0);
    level.color_start.push_back(0);
    // the nonzeros of a row in the global order of their columns, so that
    // every process that relaxes a patch sums in the same order (the global
    // indices looked up once: Partitioner::local_to_global() in the
    // comparison made the sort a fifth of the set-up)
    std::vector<types::global_dof_index> global(matrix.m());
    for (unsigned int i = 0; i < matrix.m(); ++i)
      global[i] = partitioner->local_to_global(i);
    std::vector<std::pair<types::global_dof_index, double>> entries;
    auto sorted_row = [&](const types::global_dof_index row) -> const auto & {
      entries.clear();
      for (auto e = matrix.begin(row); e != matrix.end(row); ++e)
        if (e->value() != 0.)
          entries.emplace_back(e->column(), e->value());
      std::sort(entries.begin(), entries.end(), [&](const auto &a, const auto &b) {
        return global[a.first] < global[b.first];
      });
      return entries;
    };
    std::vector<unsigned int> local(matrix.m(), numbers::invalid_unsigned_int);
    // the patch of each DoF among the patches of the current color
    std::vector<unsigned int> patch_of(matrix.m(), numbers::invalid_unsigned_int);
    unsigned int              n_qps = 0;
    for (const auto &color : by_color)
      {
        // (only DoFs that move: reading a fixed DoF of another patch is
        // harmless)
        for (const unsigned int p : color)
          for (const auto dof : patches[p])
            if (role[dof] != DoFRole::fixed && matrix.diag_element(dof) > 0)
              patch_of[dof] = p;
        for (const unsigned int p : color)
          {
            const auto   first       = level.neighbors.size();
            bool         any_bounded = false;
            unsigned int n           = 0;
            for (const auto dof : patches[p])
              if (role[dof] != DoFRole::fixed && matrix.diag_element(dof) > 0)
                {
                  local[dof] = n++;
                  level.neighbors.push_back(dof);
                  level.bounded.push_back(role[dof] == DoFRole::bounded);
                  any_bounded |= role[dof] == DoFRole::bounded;
                }
            for (unsigned int a = 0; a < n; ++a)
              {
                for (const auto &e : sorted_row(level.neighbors[first + a]))
                  {
                    // two patches of one color must not be coupled: they
                    // are relaxed at the same time
                    AssertThrow(patch_of[e.first] == numbers::invalid_unsigned_int ||
                                  patch_of[e.first] == p,
                                ExcMessage("PatchSmoother: the matrix couples two "
                                           "patches of one color"));
                    if (local[e.first] == numbers::invalid_unsigned_int)
                      {
                        local[e.first] = level.neighbors.size() - first;
                        level.neighbors.push_back(e.first);
                      }
                    level.columns.push_back(local[e.first]);
                    level.values.push_back(e.second);
                  }
                level.row_start.push_back(level.columns.size());
              }
            const auto m = level.neighbors.size() - first;
            AssertThrow(m <= std::numeric_limits<std::uint16_t>::max() + std::size_t(1),
                        ExcMessage("PatchSmoother: a patch's rows reach more than 65536 DoFs"));
            for (auto j = first; j < level.neighbors.size(); ++j)
              local[level.neighbors[j]] = numbers::invalid_unsigned_int;
            if (n == 0)
              continue;
            level.counted.push_back(level.neighbors[first] < n_owned);
            level.box_qp.push_back(any_bounded ? n_qps++ : numbers::invalid_unsigned_int);
            level.start.push_back(level.bounded.size());
            level.neighbor_start.push_back(level.neighbors.size());
            level.inverse_start.push_back(level.inverse_start.back() + n * (n + 1) / 2);
          }
        level.color_start.push_back(level.box_qp.size());
        for (const unsigned int p : color)
          for (const auto dof : patches[p])
            patch_of[dof] = numbers::invalid_unsigned_int;
      }

    // The inverses (in parallel, patch by patch) of the patch matrices
    // (their upper triangles), and a BoxQP for patches with a bounded DoF.
    level.inverse.resize(level.inverse_start.back());
    level.qps.resize(n_qps);
    for_subranges(
      0u,
      static_cast<unsigned int>(level.box_qp.size()),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int k = begin; k < end; ++k)
          {
            const unsigned int n    = level.start[k + 1] - level.start[k];
            // the patch matrix from the rows: the patch DoFs are the first
            // n positions of the neighbourhood
            FullMatrix<double> M(n, n);
            for (unsigned int a = 0; a < n; ++a)
              for (std::size_t j = level.row_start[level.start[k] + a];
                   j < level.row_start[level.start[k] + a + 1];
                   ++j)
                if (level.columns[j] < n)
                  M(a, level.columns[j]) = level.values[j];
            BoxQP   qp(M);
            double *inverse = level.inverse.data() + level.inverse_start[k];
            for (unsigned int a = 0; a < n; ++a)
              for (unsigned int b = a; b < n; ++b)
                *inverse++ = qp.inverse_entry(a, b);
            if (level.box_qp[k] != numbers::invalid_unsigned_int)
              level.qps[level.box_qp[k]] = std::move(qp);
          }
      },
      16);
  }


  void
  PatchSmoother::set_linear_roles(const unsigned int l, const std::vector<DoFRole> &linear_role)
  {
    Level &level = levels[l];
    level.linear_patch.resize(level.qps.size());
    for (unsigned int k = 0; k < level.box_qp.size(); ++k)
      if (level.box_qp[k] != numbers::invalid_unsigned_int)
        {
          const auto *       dofs  = level.neighbors.data() + level.neighbor_start[k];
          const unsigned int n     = level.start[k + 1] - level.start[k];
          const BoxQP &      qp    = level.qps[level.box_qp[k]];
          auto &             patch = level.linear_patch[level.box_qp[k]];
          patch.moving.clear();
          for (unsigned int a = 0; a < n; ++a)
            if (linear_role[dofs[a]] != DoFRole::fixed)
              patch.moving.push_back(a);
          const unsigned int m = patch.moving.size();
          FullMatrix<double> M(m, m);
          for (unsigned int a = 0; a < m; ++a)
            for (unsigned int b = 0; b < m; ++b)
              M(a, b) = qp.matrix_entry(patch.moving[a], patch.moving[b]);
          if (m > 0)
            M.gauss_jordan(); // pivots, as in BoxQP
          patch.inverse.assign(M.begin(), M.end());
        }
  }


  void
  PatchSmoother::set_obstacles(const unsigned int l, const LevelVector &ub)
  {
    levels[l].obstacles = &ub;
  }


  void
  PatchSmoother::relax_patches(const Level &      level,
                               const unsigned int begin,
                               const unsigned int end,
                               LevelVector &      v_vector,
                               const LevelVector &r_vector) const
  {
    // local elements, owned and ghost
    double *            v   = v_vector.begin();
    const double *      r   = r_vector.begin();
    const double *      ub  = level.obstacles->begin();
    const double        inf = std::numeric_limits<double>::infinity();
    // (the work arrays of this thread: allocating them per call cost a
    // third of a smoothing step on the coarsest levels, 42 DoFs)
    thread_local std::vector<double> g, s, c, near;
    thread_local std::vector<bool>   at_bound;
    unsigned int        increases = 0;
    for (unsigned int k = begin; k < end; ++k)
      {
        // the patch's DoFs are the first n of its neighbourhood
        const auto *       dofs = level.neighbors.data() + level.neighbor_start[k];
        const unsigned int m    = level.neighbor_start[k + 1] - level.neighbor_start[k];
        const unsigned int n    = level.start[k + 1] - level.start[k];
        const double *     inv  = level.inverse.data() + level.inverse_start[k];
        g.resize(n);
        s.resize(n);
        c.resize(n);
        near.resize(m);
        for (unsigned int j = 0; j < m; ++j)
          near[j] = v[dofs[j]];
        const bool linear_patch =
          level.linear && level.box_qp[k] != numbers::invalid_unsigned_int;
        for (unsigned int a = 0; a < n; ++a)
          {
            const auto           i      = dofs[a];
            const std::size_t    first  = level.row_start[level.start[k] + a];
            const std::size_t    last   = level.row_start[level.start[k] + a + 1];
            const std::uint16_t *column = level.columns.data();
            const double *       value  = level.values.data();
            double               gi     = r[i];
            for (std::size_t e = first; e < last; ++e)
              gi -= value[e] * near[column[e]];
            g[a] = gi;
            s[a] = level.bounded[level.start[k] + a] ? std::max(0., ub[i] - v[i]) : inf;
          }
        if (linear_patch)
          {
            // the linear problem: the fixed DoFs stay, the others have no
            // bound
            const auto &       patch    = level.linear_patch[level.box_qp[k]];
            const unsigned int n_moving = patch.moving.size();
            double             gc = 0, scale = 0;
            for (unsigned int a = 0; a < n_moving; ++a)
              {
                double ca = 0;
                for (unsigned int b = 0; b < n_moving; ++b)
                  ca += patch.inverse[a * n_moving + b] * g[patch.moving[b]];
                c[a] = ca;
                gc += g[patch.moving[a]] * ca;
                scale += std::abs(g[patch.moving[a]] * ca);
              }
            for (unsigned int a = 0; a < n_moving; ++a)
              v[dofs[patch.moving[a]]] += c[a];
            if (-0.5 * gc > 1e-10 * scale + 1e-300 && level.counted[k])
              ++increases;
            continue;
          }
        // the unconstrained patch minimizer c = M^{-1} g (the upper
        // triangle of M^{-1} by rows), and the change of the objective,
        // 1/2 c^T M c - g^T c = -1/2 g^T c
        std::fill(c.begin(), c.end(), 0.);
        for (unsigned int a = 0; a < n; ++a)
          {
            double ca = c[a] + inv[0] * g[a];
            for (unsigned int b = a + 1; b < n; ++b)
              {
                ca += inv[b - a] * g[b];
                c[b] += inv[b - a] * g[a];
              }
            c[a] = ca;
            inv += n - a;
          }
        bool   feasible = true;
        double gc       = 0;
        for (unsigned int a = 0; a < n; ++a)
          {
            gc += g[a] * c[a];
            feasible &= c[a] <= s[a];
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
            v[i]         = at_bound[a] ? ub[i] : v[i] + c[a];
            scale += std::abs(g[a] * c[a]);
          }
        // exact minimization on the patch: the change is <= 0 up to
        // round-off relative to its own terms
        if (change > 1e-10 * scale + 1e-300 && level.counted[k])
          ++increases;
      }
    if (increases > 0)
      n_increases += increases;
  }


  void
  PatchSmoother::smooth(const unsigned int l,
                        LevelVector &      v,
                        const LevelVector &r) const
  {
    const Level &      level    = levels[l];
    const unsigned int n_colors = level.color_start.size() - 1;
    AssertThrow(!level.linear || level.linear_patch.size() == level.qps.size(),
                ExcMessage("PatchSmoother: linear roles used before set_linear_roles()"));
    update_ghosts(r);
    update_ghosts(*level.obstacles);
    update_ghosts(v);
    for (unsigned int step = 0; step < steps; ++step)
      for (unsigned int cc = 0; cc < n_colors; ++cc)
        {
          const unsigned int color = backward ? n_colors - 1 - cc : cc;
          // the patches of one color are independent: any split among
          // threads gives the same result
          for_subranges(
            level.color_start[color],
            level.color_start[color + 1],
            [&](const unsigned int begin, const unsigned int end) {
              relax_patches(level, begin, end, v, r);
            },
            64);
          // the owners' new values to the other processes' ghost copies
          update_ghosts(v);
        }
  }


  void
  PatchSmoother::clear()
  {
    for (auto &level : levels)
      level = Level();
  }
} // namespace FoslsContact
