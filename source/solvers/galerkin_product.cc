#include <fosls_contact/solvers/galerkin_product.h>

#include <deal.II/base/memory_consumption.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/thread_local_storage.h>

#include <fosls_contact/qp/product_pattern.h>

#include <map>
#include <algorithm>
#include <set>

namespace FoslsContact
{
  void
  GalerkinProduct::initialize(
    const SparsityPattern &                                    pattern,
    const SparsityPattern &                                    fine_pattern,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &fine_partitioner,
    const SparsityPattern &                                    coarse_pattern,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &coarse_partitioner)
  {
    comm                       = coarse_partitioner->get_mpi_communicator();
    const unsigned int n_owned = fine_partitioner->locally_owned_size();
    n_coarse_local             = pattern.n_cols();
    n_coarse_owned             = coarse_partitioner->locally_owned_size();
    transpose_pattern(pattern, n_owned);

    // the pattern of A P on the owned rows of A, for the room of each row
    // in compute() and the columns below; not kept
    const ProductPattern product(fine_pattern, pattern, n_owned);
    product_row_length.resize(n_owned);
    for (unsigned int r = 0; r < n_owned; ++r)
      product_row_length[r] = product.row_length(r);
    // the columns of P^T (A P) in coarse row j: those of the rows of A P
    // at column j of P
    auto for_each_column = [&](const unsigned int j, const auto &f) {
      for (std::size_t k = transpose_start[j]; k < transpose_start[j + 1]; ++k)
        for (std::size_t q = product.start[transpose_row[k]];
             q < product.start[transpose_row[k] + 1];
             ++q)
          f(product.columns[q]);
    };

    // the columns of each owned coarse row outside the result's pattern
    // (marked per row: SparsityPattern::exists() scans the row, which
    // made this loop quadratic in the row length)
    extra_start.assign(1, 0);
    extra_columns.clear();
    std::vector<unsigned int> seen_in_row(n_coarse_local, numbers::invalid_unsigned_int);
    std::vector<unsigned int> columns;
    for (unsigned int j = 0; j < n_coarse_owned; ++j)
      {
        for (auto e = coarse_pattern.begin(j); e != coarse_pattern.end(j); ++e)
          seen_in_row[e->column()] = j;
        columns.clear();
        for_each_column(j, [&](const unsigned int c) {
          if (seen_in_row[c] != j)
            {
              seen_in_row[c] = j;
              columns.push_back(c);
            }
        });
        std::sort(columns.begin(), columns.end());
        extra_columns.insert(extra_columns.end(), columns.begin(), columns.end());
        extra_start.push_back(extra_columns.size());
      }

    // the ghost coarse rows that get parts here, and their columns
    ghost_row.clear();
    ghost_start.assign(1, 0);
    ghost_columns.clear();
    for (unsigned int j = n_coarse_owned; j < n_coarse_local; ++j)
      {
        std::set<unsigned int> columns;
        for_each_column(j, [&](const unsigned int c) { columns.insert(c); });
        if (columns.empty())
          continue;
        ghost_row.push_back(j);
        ghost_columns.insert(ghost_columns.end(), columns.begin(), columns.end());
        ghost_start.push_back(ghost_columns.size());
      }
    ghost_values.resize(ghost_columns.size());
    set_up_ghost_messages(*coarse_partitioner, coarse_pattern);
  }


  void
  GalerkinProduct::transpose_pattern(const SparsityPattern &pattern, const unsigned int n_owned)
  {
    // the columns of the owned rows of P
    transpose_start.assign(n_coarse_local + 1, 0);
    for (unsigned int r = 0; r < n_owned; ++r)
      for (auto e = pattern.begin(r); e != pattern.end(r); ++e)
        ++transpose_start[e->column() + 1];
    for (unsigned int j = 0; j < n_coarse_local; ++j)
      transpose_start[j + 1] += transpose_start[j];
    transpose_row.resize(transpose_start.back());
    transpose_position.resize(transpose_start.back());
    std::vector<std::size_t> next(transpose_start.begin(), transpose_start.end() - 1);
    for (unsigned int r = 0; r < n_owned; ++r)
      for (auto e = pattern.begin(r); e != pattern.end(r); ++e)
        {
          const auto k          = next[e->column()]++;
          transpose_row[k]      = r;
          transpose_position[k] = e->global_index();
        }
  }


  void
  GalerkinProduct::set_up_ghost_messages(const Utilities::MPI::Partitioner &coarse_partitioner,
                                         const SparsityPattern &            coarse_pattern)
  {
    // who owns the ghost rows (they are sorted by global index, the
    // owners' ranges too), and the owners' view of the entries
    send_to.clear();
    receive_from.clear();
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    std::vector<types::global_dof_index> rows;
    for (const unsigned int j : ghost_row)
      rows.push_back(coarse_partitioner.local_to_global(j));
    const std::vector<unsigned int> owner = owners(coarse_partitioner, rows);
    std::map<unsigned int, std::vector<types::global_dof_index>> entries;
    for (unsigned int r = 0; r < ghost_row.size(); ++r)
      {
        if (send_to.empty() || send_to.back().first != owner[r])
          send_to.push_back({owner[r], {r, r}});
        send_to.back().second.second = r + 1;
        for (std::size_t k = ghost_start[r]; k < ghost_start[r + 1]; ++k)
          {
            entries[owner[r]].push_back(rows[r]);
            entries[owner[r]].push_back(coarse_partitioner.local_to_global(ghost_columns[k]));
          }
      }
    const auto received = Utilities::MPI::some_to_some(comm, entries);
    for (const auto &[rank, list] : received)
      {
        std::vector<std::pair<unsigned int, unsigned int>> positions;
        for (std::size_t k = 0; k + 1 < list.size(); k += 2)
          {
            const unsigned int row = coarse_partitioner.global_to_local(list[k]);
            unsigned int       col = numbers::invalid_unsigned_int;
            if (coarse_partitioner.in_local_range(list[k + 1]) ||
                coarse_partitioner.is_ghost_entry(list[k + 1]))
              col = coarse_partitioner.global_to_local(list[k + 1]);
            if (col == numbers::invalid_unsigned_int || !coarse_pattern.exists(row, col))
              positions.emplace_back(numbers::invalid_unsigned_int, 0);
            else
              positions.emplace_back(row, col);
          }
        receive_from.emplace_back(rank, positions);
      }
  }


  namespace
  {
    /**
     * Owned fine rows per block of compute(): the buffer holds the rows
     * of A P of one block (12 bytes per entry: column and value) instead
     * of the product of the whole level, a few MB; a coarse row is reached
     * by a few blocks, and each visit loads and stores its partial sums
     * once.
     */
    constexpr unsigned int block_rows = 16384;

    /** The message of an entry of the product outside the coarse pattern. */
    const char *const outside_pattern =
      "GalerkinProduct: a coarse operator entry outside the coupling pattern of the "
      "coarse cells";
  } // namespace


  /**
   * The work arrays of a thread: a dense row of length n_coarse_local,
   * kept zero between rows, and for every coarse column the fine row
   * that last reached it (invalid between rows).
   */
  struct GalerkinProduct::ProductWork
  {
    std::vector<double>       row;
    std::vector<unsigned int> reached_by;
  };


  /**
   * The state of one compute() across its blocks of fine rows: the
   * threads' work arrays, the block's rows of A P, and per coarse column
   * how far down its fine rows the sums have come.
   */
  struct GalerkinProduct::ProductState
  {
    ProductState(const std::vector<std::size_t> &transpose_start,
                 const unsigned int              n_coarse_local,
                 const std::size_t               n_extra)
      : thread_work(
          ProductWork{std::vector<double>(n_coarse_local, 0.),
                      std::vector<unsigned int>(n_coarse_local, numbers::invalid_unsigned_int)})
      , next(transpose_start.begin(), transpose_start.end() - 1)
      , reached_in_block(n_coarse_local, numbers::invalid_unsigned_int)
      , extra_values(n_extra, 0.)
    {}

    Threads::ThreadLocalStorage<ProductWork> thread_work;
    /**
     * next[j]: the first entry of column j of P whose fine row is in the
     * current block or a later one (a column lists its rows in increasing
     * order)
     */
    std::vector<std::size_t> next;
    /** The coarse rows the current block reaches (marked by its first row). */
    std::vector<unsigned int> reached_in_block, reached;
    /**
     * The block's rows of A P: row r - r0 has block_length[r - r0] entries
     * from block_start[r - r0] on.
     */
    std::vector<std::size_t>  block_start;
    std::vector<unsigned int> block_length, block_columns;
    std::vector<double>       block_values;
    /** The sums outside the result's pattern (extra_columns): exact zeros. */
    std::vector<double> extra_values;
  };


  void
  GalerkinProduct::compute(const SparseMatrix<double> &A,
                           const SparseMatrix<double> &P,
                           SparseMatrix<double> &      galerkin)
  {
    // the values of P in the order of its pattern (global_index)
    const SparsityPattern &P_pattern = P.get_sparsity_pattern();
    P_values.resize(P_pattern.n_nonzero_elements());
    for_subranges(
      0u,
      static_cast<unsigned int>(P.m()),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int r = begin; r < end; ++r)
          for (auto e = P.begin(r); e != P.end(r); ++e)
            P_values[e->global_index()] = e->value();
      },
      1000);

    // the sums start at zero: the owned rows of the result, the parts of
    // the ghost rows and the entries outside the pattern
    for_subranges(
      0u,
      n_coarse_owned,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int j = begin; j < end; ++j)
          for (auto e = galerkin.begin(j); e != galerkin.end(j); ++e)
            e->value() = 0.;
      },
      1000);
    std::fill(ghost_values.begin(), ghost_values.end(), 0.);
    ProductState state(transpose_start, n_coarse_local, extra_columns.size());

    const auto n_fine = static_cast<unsigned int>(product_row_length.size());
    for (unsigned int r0 = 0; r0 < n_fine; r0 += block_rows)
      {
        const unsigned int r1 = std::min(n_fine, r0 + block_rows);
        multiply_block(A, P, r0, r1, state);
        add_block(P, r0, r1, galerkin, state);
      }

    // a nonzero outside the result's pattern is an error
    for (const double value : state.extra_values)
      {
        AssertThrow(value == 0., ExcMessage(outside_pattern));
      }
    add_ghost_parts(galerkin);
  }


  void
  GalerkinProduct::multiply_block(const SparseMatrix<double> &A,
                                  const SparseMatrix<double> &P,
                                  const unsigned int          r0,
                                  const unsigned int          r1,
                                  ProductState &              state) const
  {
    state.block_start.assign(1, 0);
    for (unsigned int r = r0; r < r1; ++r)
      state.block_start.push_back(state.block_start.back() + product_row_length[r]);
    state.block_length.resize(r1 - r0);
    state.block_columns.resize(state.block_start.back());
    state.block_values.resize(state.block_start.back());

    // each row summed over the nonzeros of A's row in their order
    for_subranges(
      r0,
      r1,
      [&](const unsigned int begin, const unsigned int end) {
        ProductWork &w = state.thread_work.get();
        for (unsigned int r = begin; r < end; ++r)
          {
            unsigned int *     columns = state.block_columns.data() + state.block_start[r - r0];
            double *           values  = state.block_values.data() + state.block_start[r - r0];
            const unsigned int room    = product_row_length[r];
            unsigned int       n       = 0;
            for (auto a = A.begin(r); a != A.end(r); ++a)
              if (a->value() != 0.)
                for (auto p = P.begin(a->column()); p != P.end(a->column()); ++p)
                  {
                    const unsigned int c = p->column();
                    if (w.reached_by[c] != r)
                      {
                        AssertThrow(n < room,
                                    ExcMessage("GalerkinProduct: A or P is not on the "
                                               "pattern given to initialize()"));
                        w.reached_by[c] = r;
                        columns[n++]    = c;
                      }
                    w.row[c] += a->value() * P_values[p->global_index()];
                  }
            for (unsigned int q = 0; q < n; ++q)
              {
                values[q]                = w.row[columns[q]];
                w.row[columns[q]]        = 0.;
                w.reached_by[columns[q]] = numbers::invalid_unsigned_int;
              }
            state.block_length[r - r0] = n;
          }
      },
      200);
  }


  void
  GalerkinProduct::add_block(const SparseMatrix<double> &P,
                             const unsigned int          r0,
                             const unsigned int          r1,
                             SparseMatrix<double> &      galerkin,
                             ProductState &              state)
  {
    state.reached.clear();
    for (unsigned int r = r0; r < r1; ++r)
      for (auto p = P.begin(r); p != P.end(r); ++p)
        if (state.reached_in_block[p->column()] != r0)
          {
            state.reached_in_block[p->column()] = r0;
            state.reached.push_back(p->column());
          }
    for_subranges(
      0u,
      static_cast<unsigned int>(state.reached.size()),
      [&](const unsigned int begin, const unsigned int end) {
        std::vector<double> &row = state.thread_work.get().row;
        for (unsigned int i = begin; i < end; ++i)
          {
            const unsigned int j = state.reached[i];
            move_sums(j, row, true, galerkin, state.extra_values);
            std::size_t k = state.next[j];
            for (; k < transpose_start[j + 1] && transpose_row[k] < r1; ++k)
              {
                const double p = P_values[transpose_position[k]];
                if (p != 0.)
                  {
                    const unsigned int b = transpose_row[k] - r0;
                    for (std::size_t q = state.block_start[b];
                         q < state.block_start[b] + state.block_length[b];
                         ++q)
                      row[state.block_columns[q]] += p * state.block_values[q];
                  }
              }
            state.next[j] = k;
            move_sums(j, row, false, galerkin, state.extra_values);
          }
      },
      64);
  }


  void
  GalerkinProduct::move_sums(const unsigned int    j,
                             std::vector<double> & row,
                             const bool            load,
                             SparseMatrix<double> &galerkin,
                             std::vector<double> & extra_values)
  {
    auto move = [&](double &stored, const unsigned int c) {
      if (load)
        row[c] = stored;
      else
        {
          stored = row[c];
          row[c] = 0.;
        }
    };
    if (j < n_coarse_owned)
      {
        for (auto e = galerkin.begin(j); e != galerkin.end(j); ++e)
          if (load)
            row[e->column()] = e->value();
          else
            {
              e->value()       = row[e->column()];
              row[e->column()] = 0.;
            }
        for (std::size_t k = extra_start[j]; k < extra_start[j + 1]; ++k)
          move(extra_values[k], extra_columns[k]);
      }
    else
      {
        const std::size_t r =
          std::lower_bound(ghost_row.begin(), ghost_row.end(), j) - ghost_row.begin();
        for (std::size_t k = ghost_start[r]; k < ghost_start[r + 1]; ++k)
          move(ghost_values[k], ghost_columns[k]);
      }
  }

  void
  GalerkinProduct::add_ghost_parts(SparseMatrix<double> &galerkin)
  {
    // the parts of the rows owned elsewhere to their owners, added here in
    // the order of the sending processes
    if (send_to.empty() && receive_from.empty())
      return;
    std::vector<std::vector<double>> receive_buffers(receive_from.size());
    std::vector<std::pair<unsigned int, ArrayView<const double>>> to;
    std::vector<std::pair<unsigned int, ArrayView<double>>>       from;
    for (const auto &[rank, range] : send_to)
      {
        const std::size_t first = ghost_start[range.first], last = ghost_start[range.second];
        to.emplace_back(rank, make_array_view(ghost_values.cbegin() + first,
                                              ghost_values.cbegin() + last));
      }
    for (unsigned int s = 0; s < receive_from.size(); ++s)
      {
        receive_buffers[s].resize(receive_from[s].second.size());
        from.emplace_back(receive_from[s].first, make_array_view(receive_buffers[s]));
      }
    exchange(comm, 4712, to, from);
    for (unsigned int s = 0; s < receive_from.size(); ++s)
      for (std::size_t k = 0; k < receive_buffers[s].size(); ++k)
        {
          const auto &[row, col] = receive_from[s].second[k];
          if (row == numbers::invalid_unsigned_int)
            {
              AssertThrow(receive_buffers[s][k] == 0., ExcMessage(outside_pattern));
            }
          else if (receive_buffers[s][k] != 0.)
            galerkin.add(row, col, receive_buffers[s][k]);
        }
  }


  void
  GalerkinProduct::Tvmult(LevelVector &dst, const LevelVector &src) const
  {
    for_subranges(
      0u,
      n_coarse_local,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int j = begin; j < end; ++j)
          {
            double sum = 0;
            for (std::size_t k = transpose_start[j]; k < transpose_start[j + 1]; ++k)
              sum += P_values[transpose_position[k]] * src.local_element(transpose_row[k]);
            dst.local_element(j) = sum;
          }
      },
      500);
    // the parts of the ghost entries to their owners (collective)
    send_ghost_parts(dst, VectorOperation::add);
  }

  std::size_t
  GalerkinProduct::memory_consumption() const
  {
    using MemoryConsumption::memory_consumption;
    return memory_consumption(P_values) + memory_consumption(transpose_start) +
           memory_consumption(transpose_row) + memory_consumption(transpose_position) +
           memory_consumption(extra_start) + memory_consumption(extra_columns) +
           memory_consumption(product_row_length) +
           memory_consumption(ghost_row) + memory_consumption(ghost_start) +
           memory_consumption(ghost_columns) + memory_consumption(ghost_values);
  }
} // namespace FoslsContact
