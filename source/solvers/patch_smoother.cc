#include <fosls_contact/solvers/patch_smoother.h>

#include <deal.II/base/parallel.h>
#include <deal.II/base/thread_local_storage.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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
    // The layout is counted first and then filled in place, patch by patch
    // in parallel: every array is allocated once, at its size, and left
    // uninitialized until the fill. Measured by hand on level 9 of the
    // square (2 threads): the finest two levels took 0.50 s when the arrays
    // grew serially (a third of the solve; reallocations, their page faults
    // and the zeroing), 0.19 s now. A parallel layout in pieces, copied into
    // the packed arrays, needed both at once: 18% more peak memory on the 3D
    // ball at level 5, against 1% less now.
    Level &level = levels[l];
    level.obstacles = nullptr;
    level.linear    = false;
    level.linear_patch.clear();
    const unsigned int n_owned = partitioner->locally_owned_size();
    const unsigned int n_dofs  = matrix.m();
    auto moves = [&](const types::global_dof_index dof) {
      return role[dof] != DoFRole::fixed && matrix.diag_element(dof) > 0;
    };

    // The patches in color order, each with the DoFs that can move (not
    // fixed, not switched off by a zero diagonal); patches without any are
    // dropped.
    std::vector<std::vector<unsigned int>> by_color(n_colors);
    for (unsigned int p = 0; p < patches.size(); ++p)
      by_color[patch_color[p]].push_back(p);
    std::vector<types::global_dof_index> patch_dofs;
    unsigned int                         n_qps = 0;
    level.start.assign(1, 0);
    level.color_start.assign(1, 0);
    level.bounded.clear();
    level.counted.clear();
    level.box_qp.clear();
    for (const auto &color : by_color)
      {
        for (const unsigned int p : color)
          {
            const auto first       = patch_dofs.size();
            bool       any_bounded = false;
            for (const auto dof : patches[p])
              if (moves(dof))
                {
                  patch_dofs.push_back(dof);
                  level.bounded.push_back(role[dof] == DoFRole::bounded);
                  any_bounded |= role[dof] == DoFRole::bounded;
                }
            if (patch_dofs.size() == first)
              continue;
            level.counted.push_back(patch_dofs[first] < n_owned);
            level.box_qp.push_back(any_bounded ? n_qps++ : numbers::invalid_unsigned_int);
            level.start.push_back(patch_dofs.size());
          }
        level.color_start.push_back(level.box_qp.size());
      }
    const unsigned int n_patches = level.box_qp.size();

    // Count: the nonzeros of every patch row, and the size of every
    // neighbourhood (the patch DoFs, then the other columns of their rows).
    // The marks of a thread's neighbourhood are reset after every patch.
    struct Work
    {
      std::vector<unsigned int>                               local;
      std::vector<types::global_dof_index>                    marked;
      std::vector<std::pair<types::global_dof_index, double>> entries;
      FullMatrix<double>                                      matrix;
    };
    Threads::ThreadLocalStorage<Work> thread_work;
    auto work = [&]() -> Work & {
      Work &w = thread_work.get();
      if (w.local.size() != n_dofs)
        w.local.assign(n_dofs, numbers::invalid_unsigned_int);
      return w;
    };
    std::atomic<bool> too_wide{false};
    level.row_start.assign(patch_dofs.size() + 1, 0);
    level.neighbor_start.assign(n_patches + 1, 0);
    level.inverse_start.assign(n_patches + 1, 0);
    for_subranges(
      0u,
      n_patches,
      [&](const unsigned int begin, const unsigned int end) {
        Work &w      = work();
        auto &local  = w.local;
        auto &marked = w.marked;
        for (unsigned int k = begin; k < end; ++k)
          {
            const auto *dofs = patch_dofs.data() + level.start[k];
            const auto  n    = level.start[k + 1] - level.start[k];
            marked.assign(dofs, dofs + n);
            for (unsigned int a = 0; a < n; ++a)
              local[dofs[a]] = a;
            for (unsigned int a = 0; a < n; ++a)
              {
                std::size_t nonzeros = 0;
                for (auto e = matrix.begin(dofs[a]); e != matrix.end(dofs[a]); ++e)
                  if (e->value() != 0.)
                    {
                      ++nonzeros;
                      if (local[e->column()] == numbers::invalid_unsigned_int)
                        {
                          local[e->column()] = marked.size();
                          marked.push_back(e->column());
                        }
                    }
                level.row_start[level.start[k] + a + 1] = nonzeros;
              }
            too_wide = too_wide || marked.size() > std::numeric_limits<std::uint16_t>::max() + 1u;
            level.neighbor_start[k + 1] = marked.size();
            level.inverse_start[k + 1]  = n * (n + 1) / 2;
            for (const auto dof : marked)
              local[dof] = numbers::invalid_unsigned_int;
          }
      },
      64);
    AssertThrow(!too_wide,
                ExcMessage("PatchSmoother: a patch's rows reach more than 65536 DoFs"));
    std::partial_sum(level.row_start.begin(), level.row_start.end(), level.row_start.begin());
    std::partial_sum(level.neighbor_start.begin(),
                     level.neighbor_start.end(),
                     level.neighbor_start.begin());
    std::partial_sum(level.inverse_start.begin(),
                     level.inverse_start.end(),
                     level.inverse_start.begin());
    // (uninitialized: the fill writes every entry, and its threads touch
    // the pages first; zeroing 150 MB on level 9 took a fifth of the set-up)
    auto allocate = [](auto &array, const std::size_t size) {
      if (size > array.capacity())
        array.clear(); // no copy of the old entries
      array.resize_fast(size);
    };
    allocate(level.neighbors, level.neighbor_start.back());
    allocate(level.columns, level.row_start.back());
    allocate(level.values, level.row_start.back());
    allocate(level.inverse, level.inverse_start.back());
    level.qps.clear();
    level.qps.resize(n_qps);

    // Fill, color by color: the rows with the nonzeros in the global order
    // of their columns, so that every process that relaxes a patch sums in
    // the same order (global indices looked up once: local_to_global() in
    // the comparison made the sort a fifth of the set-up), columns numbered
    // within the neighbourhood; then the inverse of the patch matrix (its
    // upper triangle), and a BoxQP for a patch with a bounded DoF.
    std::vector<types::global_dof_index> global(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      global[i] = partitioner->local_to_global(i);
    // the patch of each DoF among the patches of the current color: two
    // patches of one color must not be coupled, they are relaxed at the
    // same time
    std::vector<unsigned int> patch_of(n_dofs, numbers::invalid_unsigned_int);
    std::atomic<bool>         coupled{false};
    for (unsigned int color = 0; color < n_colors; ++color)
      {
        const unsigned int begin = level.color_start[color];
        const unsigned int end   = level.color_start[color + 1];
        for (unsigned int k = begin; k < end; ++k)
          for (auto j = level.start[k]; j < level.start[k + 1]; ++j)
            {
              coupled = coupled || patch_of[patch_dofs[j]] != numbers::invalid_unsigned_int;
              patch_of[patch_dofs[j]] = k;
            }
        for_subranges(
          begin,
          end,
          [&](const unsigned int begin, const unsigned int end) {
            Work &w = work();
            for (unsigned int k = begin; k < end; ++k)
              {
                const auto   n         = level.start[k + 1] - level.start[k];
                auto *       neighbors = level.neighbors.data() + level.neighbor_start[k];
                unsigned int m         = n;
                std::copy(patch_dofs.data() + level.start[k],
                          patch_dofs.data() + level.start[k + 1],
                          neighbors);
                for (unsigned int a = 0; a < n; ++a)
                  w.local[neighbors[a]] = a;
                FullMatrix<double> &M = w.matrix;
                M.reinit(n, n);
                for (unsigned int a = 0; a < n; ++a)
                  {
                    w.entries.clear();
                    for (auto e = matrix.begin(neighbors[a]); e != matrix.end(neighbors[a]);
                         ++e)
                      if (e->value() != 0.)
                        w.entries.emplace_back(e->column(), e->value());
                    // (an insertion sort: a row comes sorted but for its
                    // diagonal, and for ghost columns on many processes)
                    for (auto e = w.entries.begin() + 1; e < w.entries.end(); ++e)
                      for (auto f = e; f != w.entries.begin() &&
                                       global[f->first] < global[(f - 1)->first];
                           --f)
                        std::iter_swap(f, f - 1);
                    auto j = level.row_start[level.start[k] + a];
                    for (const auto &[column, value] : w.entries)
                      {
                        if (patch_of[column] != numbers::invalid_unsigned_int &&
                            patch_of[column] != k)
                          coupled = true;
                        if (w.local[column] == numbers::invalid_unsigned_int)
                          {
                            w.local[column] = m;
                            neighbors[m++]  = column;
                          }
                        level.columns[j] = w.local[column];
                        level.values[j]  = value;
                        if (w.local[column] < n)
                          M(a, w.local[column]) = value;
                        ++j;
                      }
                  }
                for (unsigned int j = 0; j < m; ++j)
                  w.local[neighbors[j]] = numbers::invalid_unsigned_int;

                // (the inverse as BoxQP computes it, without the BoxQP where
                // no bound can be reached)
                if (level.box_qp[k] != numbers::invalid_unsigned_int)
                  {
                    level.qps[level.box_qp[k]] = BoxQP(M);
                    M = level.qps[level.box_qp[k]].inverse_matrix();
                  }
                else
                  M.gauss_jordan();
                double *inverse = level.inverse.data() + level.inverse_start[k];
                for (unsigned int a = 0; a < n; ++a)
                  for (unsigned int b = a; b < n; ++b)
                    *inverse++ = M(a, b);
              }
          },
          16);
        for (auto j = level.start[begin]; j < level.start[end]; ++j)
          patch_of[patch_dofs[j]] = numbers::invalid_unsigned_int;
      }
    AssertThrow(!coupled, ExcMessage("PatchSmoother: the matrix couples two patches of one color"));
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
            // (a NaN correction counts as feasible: only a patch with a
            // bounded DoF has a BoxQP, and the monitor stops a run whose
            // iterate is not finite)
            feasible &= !(c[a] > s[a]);
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
          // threads gives the same result (pieces of 16 patches: level 5 of
          // the square, whose colors have about 70 patches on the finest
          // level, took 0.35 instead of 0.37 us per cycle per DoF with 64,
          // best of 15 solves each, measured by hand; levels 6-9 unchanged)
          for_subranges(
            level.color_start[color],
            level.color_start[color + 1],
            [&](const unsigned int begin, const unsigned int end) {
              relax_patches(level, begin, end, v, r);
            },
            16);
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
