#include <fosls_contact/solvers/packed_patches.h>

#include <deal.II/base/memory_consumption.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/thread_local_storage.h>
#include <deal.II/lac/full_matrix.h>

#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/solvers/spd_inverse.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>

namespace FoslsContact
{
  namespace
  {
    /**
     * Patches per task of the parallel count and fill: a patch's rows are
     * counted in a few hundred operations, while filling one (rows,
     * inverse) costs about as much as relaxing it.
     */
    constexpr unsigned int count_grain = 64, fill_grain = 16;

    /**
     * The work arrays of one thread: the position of every local DoF in
     * the current patch's neighbourhood (invalid outside it, reset after
     * every patch), the neighbourhood, a row and the patch matrix.
     */
    struct PatchWork
    {
      std::vector<unsigned int>                               local;
      std::vector<types::global_dof_index>                    marked;
      std::vector<std::pair<types::global_dof_index, double>> entries;
      FullMatrix<double>                                      matrix;
    };

    class ThreadWork
    {
    public:
      explicit ThreadWork(const unsigned int n_dofs)
        : n_dofs(n_dofs)
      {}
      PatchWork &get()
      {
        PatchWork &w = storage.get();
        if (w.local.size() != n_dofs)
          w.local.assign(n_dofs, numbers::invalid_unsigned_int);
        return w;
      }

    private:
      const unsigned int                    n_dofs;
      Threads::ThreadLocalStorage<PatchWork> storage;
    };


    /**
     * The patches in color order, each with the DoFs that can move (not
     * fixed, not switched off by a zero diagonal) appended to
     * @p patch_dofs; patches without any are dropped.
     */
    void
    select_patches(PackedPatches &                                          level,
                   const SparseMatrix<double> &                             matrix,
                   const std::vector<std::vector<types::global_dof_index>> &patches,
                   const std::vector<unsigned int> &                        patch_color,
                   const unsigned int                                       n_colors,
                   const std::vector<DoFRole> &                             role,
                   const unsigned int                                       n_owned,
                   std::vector<types::global_dof_index> &                   patch_dofs)
    {
      auto moves = [&](const types::global_dof_index dof) {
        return role[dof] != DoFRole::fixed && matrix.diag_element(dof) > 0;
      };
      std::vector<std::vector<unsigned int>> by_color(n_colors);
      for (unsigned int p = 0; p < patches.size(); ++p)
        by_color[patch_color[p]].push_back(p);
      unsigned int n_qps = 0;
      level.start.assign(1, 0);
      level.color_start.assign(1, 0);
      level.roles.clear();
      level.counted.clear();
      level.box_qp.clear();
      level.friction.clear();
      for (const auto &color : by_color)
        {
          for (const unsigned int p : color)
            {
              const auto first       = patch_dofs.size();
              bool       any_bounded = false, any_friction = false;
              for (const auto dof : patches[p])
                if (moves(dof))
                  {
                    patch_dofs.push_back(dof);
                    level.roles.push_back(role[dof]);
                    any_friction |= role[dof] == DoFRole::traction || role[dof] == DoFRole::slip;
                    // (a friction DoF has bounds or a kink where the
                    // level relaxes with friction terms)
                    any_bounded |= role[dof] == DoFRole::bounded || any_friction;
                  }
              if (patch_dofs.size() == first)
                continue;
              level.counted.push_back(patch_dofs[first] < n_owned);
              level.friction.push_back(any_friction);
              level.box_qp.push_back(any_bounded ? n_qps++ : numbers::invalid_unsigned_int);
              level.start.push_back(patch_dofs.size());
            }
          level.color_start.push_back(level.box_qp.size());
        }
      level.qps.clear();
      level.qps.resize(n_qps);
    }


    /**
     * Count the nonzeros of every patch row and the size of every
     * neighbourhood (the patch DoFs, then the other columns of their
     * rows), as offsets; then allocate the packed arrays, uninitialized:
     * the fill writes every entry, and its threads touch the pages first
     * (zeroing the arrays was a large part of the set-up). Rows read
     * from the matrix: no rows, and a neighbourhood is the patch.
     */
    void
    lay_out(PackedPatches &                             level,
            const SparseMatrix<double> &                matrix,
            const std::vector<types::global_dof_index> &patch_dofs,
            ThreadWork &                                thread_work)
    {
      const unsigned int n_patches = level.box_qp.size();
      std::atomic<bool>  too_wide{false};
      level.row_start.assign(level.matrix ? 0 : patch_dofs.size() + 1, 0);
      level.neighbor_start.assign(n_patches + 1, 0);
      level.inverse_start.assign(n_patches + 1, 0);
      if (level.matrix)
        for (unsigned int k = 0; k < n_patches; ++k)
          {
            const auto n                = level.start[k + 1] - level.start[k];
            level.neighbor_start[k + 1] = n;
            level.inverse_start[k + 1]  = n * (n + 1) / 2;
          }
      else
        for_subranges(
          0u,
          n_patches,
          [&](const unsigned int begin, const unsigned int end) {
            PatchWork &w      = thread_work.get();
            auto &     local  = w.local;
            auto &     marked = w.marked;
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
                too_wide =
                  too_wide || marked.size() > std::numeric_limits<std::uint16_t>::max() + 1u;
                level.neighbor_start[k + 1] = marked.size();
                level.inverse_start[k + 1]  = n * (n + 1) / 2;
                for (const auto dof : marked)
                  local[dof] = numbers::invalid_unsigned_int;
              }
          },
          count_grain);
      AssertThrow(!too_wide,
                  ExcMessage("PatchSmoother: a patch's rows reach more than 65536 DoFs"));
      for (auto *offsets : {&level.row_start, &level.neighbor_start, &level.inverse_start})
        std::partial_sum(offsets->begin(), offsets->end(), offsets->begin());
      auto allocate = [](auto &array, const std::size_t size) {
        if (size > array.capacity() || size == 0)
          array.clear(); // no copy of the old entries; no rows kept
        array.resize_fast(size);
      };
      const std::size_t n_row_entries = level.row_start.empty() ? 0 : level.row_start.back();
      allocate(level.neighbors, level.neighbor_start.back());
      allocate(level.columns, n_row_entries);
      allocate(level.values, n_row_entries);
      allocate(level.inverse, level.inverse_start.back());
    }


    /**
     * Fill patch k: its neighbourhood, its rows with the nonzeros in the
     * global order of their columns (@p global; looked up once:
     * local_to_global() in the comparison made the sort a fifth of the
     * set-up), columns numbered within the neighbourhood, and the upper
     * triangle of the inverse of the patch matrix (with a BoxQP for a
     * patch with a bounded DoF); with rows read from the matrix only the
     * patch's DoFs and the inverse. Sets @p coupled where a row reaches a
     * DoF of another patch of the color (@p patch_of).
     */
    void
    fill_patch(PackedPatches &                             level,
               const unsigned int                          k,
               const SparseMatrix<double> &                matrix,
               const std::vector<types::global_dof_index> &patch_dofs,
               const std::vector<types::global_dof_index> &global,
               const std::vector<unsigned int> &           patch_of,
               PatchWork &                                 w,
               std::atomic<bool> &                         coupled)
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
      if (level.matrix)
        {
          // the patch matrix and the coupling check only: the rows stay
          // in the matrix
          for (unsigned int a = 0; a < n; ++a)
            for (auto e = matrix.begin(neighbors[a]); e != matrix.end(neighbors[a]); ++e)
              if (e->value() != 0.)
                {
                  const auto column = e->column();
                  if (patch_of[column] != numbers::invalid_unsigned_int && patch_of[column] != k)
                    coupled = true;
                  if (w.local[column] != numbers::invalid_unsigned_int)
                    M(a, w.local[column]) = e->value();
                }
        }
      else
        for (unsigned int a = 0; a < n; ++a)
          {
            w.entries.clear();
            for (auto e = matrix.begin(neighbors[a]); e != matrix.end(neighbors[a]); ++e)
              if (e->value() != 0.)
                w.entries.emplace_back(e->column(), e->value());
            // (an insertion sort: a row comes sorted but for its diagonal,
            // and for ghost columns on many processes)
            for (auto e = w.entries.begin() + 1; e < w.entries.end(); ++e)
              for (auto f = e; f != w.entries.begin() && global[f->first] < global[(f - 1)->first];
                   --f)
                std::iter_swap(f, f - 1);
            auto j = level.row_start[level.start[k] + a];
            for (const auto &[column, value] : w.entries)
              {
                if (patch_of[column] != numbers::invalid_unsigned_int && patch_of[column] != k)
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

      // (the inverse as BoxQP computes it, without the BoxQP where no
      // bound can be reached)
      if (level.box_qp[k] != numbers::invalid_unsigned_int)
        {
          level.qps[level.box_qp[k]] = BoxQP(M);
          M                          = level.qps[level.box_qp[k]].inverse_matrix();
        }
      else
        invert_spd(M);
      double *inverse = level.inverse.data() + level.inverse_start[k];
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = a; b < n; ++b)
          *inverse++ = M(a, b);
    }
  } // namespace


  void
  PackedPatches::build(const SparseMatrix<double> &                              matrix,
                       const std::vector<std::vector<types::global_dof_index>> & patches,
                       const std::vector<unsigned int> &                         patch_color,
                       const unsigned int                                        n_colors,
                       const std::vector<DoFRole> &                              role,
                       const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                       const bool                                                copy_rows)
  {
    // The layout is counted first and then filled in place, patch by patch
    // in parallel: every array is allocated once, at its size, and left
    // uninitialized until the fill: arrays that grew serially cost their
    // reallocations, their page faults and the zeroing (doc/performance.md,
    // section 3). A parallel layout in pieces, copied into the packed
    // arrays, would need both at once and raise the peak memory
    // (doc/performance.md, "Figures behind the code").
    linear_patch.clear();
    const unsigned int n_dofs = matrix.m();
    // (row_defect() sums in global order only where the owned DoFs are
    // one range of global indices, as deal.II distributes them; otherwise
    // the rows are copied)
    n_owned = partitioner->locally_owned_size();
    this->matrix =
      copy_rows || !partitioner->locally_owned_range().is_contiguous() ? nullptr : &matrix;
    matrix_values = this->matrix && n_dofs > 0 ? &matrix(0, 0) : nullptr;
    ghosts_above  = n_owned;
    for (unsigned int g = n_owned; g < n_dofs; ++g)
      if (partitioner->local_to_global(g) < partitioner->local_range().first)
        ++ghosts_above;
    std::vector<types::global_dof_index> patch_dofs;
    select_patches(*this,
                   matrix,
                   patches,
                   patch_color,
                   n_colors,
                   role,
                   partitioner->locally_owned_size(),
                   patch_dofs);
    ThreadWork thread_work(n_dofs);
    lay_out(*this, matrix, patch_dofs, thread_work);

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
        const unsigned int begin = color_start[color];
        const unsigned int end   = color_start[color + 1];
        for (unsigned int k = begin; k < end; ++k)
          for (auto j = start[k]; j < start[k + 1]; ++j)
            {
              coupled = coupled || patch_of[patch_dofs[j]] != numbers::invalid_unsigned_int;
              patch_of[patch_dofs[j]] = k;
            }
        for_subranges(
          begin,
          end,
          [&](const unsigned int begin, const unsigned int end) {
            PatchWork &w = thread_work.get();
            for (unsigned int k = begin; k < end; ++k)
              fill_patch(*this, k, matrix, patch_dofs, global, patch_of, w, coupled);
          },
          fill_grain);
        for (auto j = start[begin]; j < start[end]; ++j)
          patch_of[patch_dofs[j]] = numbers::invalid_unsigned_int;
      }
    AssertThrow(!coupled, ExcMessage("PatchSmoother: the matrix couples two patches of one color"));
  }


  void
  PackedPatches::set_linear_roles(const std::vector<DoFRole> &linear_role,
                                  const PairTerms *           pair_terms)
  {
    linear_patch.resize(qps.size());
    for (unsigned int k = 0; k < box_qp.size(); ++k)
      if (box_qp[k] != numbers::invalid_unsigned_int)
        {
          const auto *       dofs  = neighbors.data() + neighbor_start[k];
          const unsigned int n     = start[k + 1] - start[k];
          const BoxQP &      qp    = qps[box_qp[k]];
          auto &             patch = linear_patch[box_qp[k]];
          patch.moving.clear();
          for (unsigned int a = 0; a < n; ++a)
            if (linear_role[dofs[a]] != DoFRole::fixed)
              patch.moving.push_back(a);
          const unsigned int m = patch.moving.size();
          FullMatrix<double> M(m, m);
          for (unsigned int a = 0; a < m; ++a)
            for (unsigned int b = 0; b < m; ++b)
              M(a, b) = qp.matrix_entry(patch.moving[a], patch.moving[b]);
          // a pair's curvature, where both of its DoFs move in this patch
          patch.pair_entries.clear();
          for (unsigned int a = 0; pair_terms != nullptr && a < m; ++a)
            {
              const auto i = dofs[patch.moving[a]];
              if (pair_terms->diagonal[i] == 0 && pair_terms->coupling[i] == 0)
                continue;
              for (unsigned int b = 0; b < m; ++b)
                if (dofs[patch.moving[b]] == pair_terms->partner[i])
                  {
                    M(a, a) += pair_terms->diagonal[i];
                    M(a, b) += pair_terms->coupling[i];
                    patch.pair_entries.push_back({patch.moving[a],
                                                  static_cast<unsigned int>(i),
                                                  pair_terms->partner[i],
                                                  pair_terms->diagonal[i],
                                                  pair_terms->coupling[i]});
                  }
            }
          if (m > 0)
            invert_spd(M);
          patch.inverse.assign(M.begin(), M.end());
        }
  }
  std::size_t
  PackedPatches::memory_consumption() const
  {
    using MemoryConsumption::memory_consumption;
    std::size_t bytes = memory_consumption(counted) + memory_consumption(start) +
                        memory_consumption(inverse_start) + memory_consumption(neighbor_start) +
                        neighbors.memory_consumption() + roles.capacity() * sizeof(DoFRole) +
                        inverse.memory_consumption() + memory_consumption(row_start) +
                        columns.memory_consumption() + values.memory_consumption() +
                        memory_consumption(box_qp) + memory_consumption(friction) +
                        memory_consumption(color_start);
    for (const BoxQP &qp : qps)
      bytes += qp.memory_consumption();
    for (const LinearPatch &patch : linear_patch)
      bytes += sizeof(LinearPatch) + memory_consumption(patch.moving) +
               memory_consumption(patch.inverse) +
               patch.pair_entries.capacity() * sizeof(LinearPatch::PairEntry);
    return bytes;
  }
} // namespace FoslsContact
