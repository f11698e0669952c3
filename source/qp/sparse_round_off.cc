#include <deal.II/base/parallel.h>

#include <fosls_contact/qp/sparse_round_off.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <vector>

namespace FoslsContact
{
  LevelVector
  diagonal(const SparseMatrix<double> &                                matrix,
           const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
  {
    LevelVector d(partitioner);
    for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
      d.local_element(i) = matrix.diag_element(i);
    update_ghosts(d);
    return d;
  }


  void
  zero_round_off(SparseMatrix<double> &                                     matrix,
                 const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                 const double                                               drop,
                 const SparseMatrix<double> *                               part)
  {
    // The rule treats a_ij and a_ji alike, so a symmetric pattern stays
    // symmetric unless one of them is within round-off of the threshold,
    // which lies in a wide gap between the round-off entries and the others
    // (ConstrainedQP::round_off_drop; the patch colors do not rely on
    // symmetry).
    // sqrt(|diagonal of A - p|) and sqrt(|diagonal of p|), local entries
    // (with the ghost entries: see LocalElements)
    const unsigned int  n_local = partitioner->locally_owned_size() + partitioner->n_ghost_indices();
    const LevelVector   a = diagonal(matrix, partitioner);
    const LocalElements a_local(a);
    std::vector<double> rest_root(n_local), part_root;
    if (part != nullptr)
      {
        const LevelVector   p = diagonal(*part, partitioner);
        const LocalElements p_local(p);
        part_root.resize(n_local);
        for (unsigned int i = 0; i < n_local; ++i)
          {
            part_root[i] = std::sqrt(std::abs(p_local(i)));
            rest_root[i] = std::sqrt(std::abs(a_local(i) - p_local(i)));
          }
      }
    else
      for (unsigned int i = 0; i < n_local; ++i)
        rest_root[i] = std::sqrt(std::abs(a_local(i)));
    for_subranges(
      0u,
      partitioner->locally_owned_size(),
      [&](const unsigned int begin, const unsigned int end) {
        for (auto i = begin; i < end; ++i)
          {
            // (p walks the part's row alongside: both rows store the
            // diagonal first, then their columns in increasing order, and
            // the part's columns are a subset of A's)
            auto p = part != nullptr ? part->begin(i) : matrix.begin(i);
            const auto p_end = part != nullptr ? part->end(i) : matrix.end(i);
            for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
              {
                double scale = rest_root[i] * rest_root[e->column()];
                if (part != nullptr)
                  {
                    if (e->column() != i)
                      while (p != p_end && (p->column() == i || p->column() < e->column()))
                        ++p;
                    if (p != p_end && p->column() == e->column() && p->value() != 0.)
                      scale += part_root[i] * part_root[e->column()];
                  }
                if (std::abs(e->value()) <= drop * scale)
                  e->value() = 0.;
              }
          }
      },
      500);
  }


  void
  compress_to_nonzeros(SparseMatrix<double> &        matrix,
                       SparsityPattern &             sparsity,
                       const std::function<void()> &release_old_pattern)
  {
    Assert(&matrix.get_sparsity_pattern() != &sparsity, ExcInternalError());
    const unsigned int n = matrix.m();
    // (the row is the loop's: an iterator's row() is a binary search over
    // all rows, which made this the slowest part of the set-up in 3D)
    const auto kept = [](const auto &entry, const types::global_dof_index row) {
      return entry.value() != 0. || entry.column() == row;
    };
    // Every pass but SparsityPattern::compress() treats the rows apart
    // (each row's entries are read and written by one thread), so they
    // run in parallel; the memory is allocated on this thread.
    constexpr unsigned int    grain = 1000;
    std::vector<unsigned int> row_lengths(n, 0);
    for_subranges(
      0u,
      n,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int i = begin; i < end; ++i)
          for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
            row_lengths[i] += kept(*e, i);
      },
      grain);
    sparsity.reinit(n, n, row_lengths);
    // a row's columns at once, sorted: SparsityPattern::add() searches
    // the row for every entry it adds
    for_subranges(
      0u,
      n,
      [&](const unsigned int begin, const unsigned int end) {
        std::vector<SparsityPattern::size_type> columns;
        for (unsigned int i = begin; i < end; ++i)
          {
            columns.clear();
            for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
              if (e->value() != 0. && e->column() != i)
                columns.push_back(e->column());
            sparsity.add_entries(i, columns.begin(), columns.end(), true);
          }
      },
      grain);
    sparsity.compress();

    // Both patterns store a row as the diagonal and then the other
    // columns in increasing order, so a new row is a subsequence of the
    // old one, and the new rows one after the other are a subsequence of
    // the old values: they move to the front of the old array in place
    // (serially: a row may move over the rows before it).
    const std::size_t n_new = sparsity.n_nonzero_elements();
    double *const     front = n > 0 ? &matrix.diag_element(0) : nullptr;
    std::size_t       k     = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        auto e = matrix.begin(i);
        for (auto s = sparsity.begin(i); s != sparsity.end(i); ++s)
          {
            while (e->column() != s->column())
              ++e;
            front[k++] = e->value();
          }
      }
    Assert(k == n_new, ExcInternalError());
    if (release_old_pattern)
      release_old_pattern();
    // the new matrix stores its entries in the same order (entry (0, 0)
    // first)
    SparseMatrix<double> compressed(sparsity);
    if (n > 0)
      {
        double *const values = &compressed.diag_element(0);
        for_subranges(
          std::size_t(0),
          n_new,
          [&](const std::size_t begin, const std::size_t end) {
            std::copy(front + begin, front + end, values + begin);
          },
          std::size_t(1) << 16);
      }
    matrix = std::move(compressed);
  }
} // namespace FoslsContact
