#include <deal.II/lac/sparse_matrix.templates.h>

#include <fosls_contact/qp/level_algebra.h>

#include <algorithm>

namespace FoslsContact
{
  LocalElements::LocalElements(LevelVector &v)
    : data(v.begin())
    , n(v.locally_owned_size() + v.get_partitioner()->n_ghost_indices())
  {}


  LocalElements::LocalElements(const LevelVector &v)
    : data(const_cast<double *>(v.begin()))
    , n(v.locally_owned_size() + v.get_partitioner()->n_ghost_indices())
  {}


  CommunicationCounter &
  communication()
  {
    static CommunicationCounter counter;
    return counter;
  }


  void
  update_ghosts(const LevelVector &v)
  {
    const auto &p = *v.get_partitioner();
    if (Utilities::MPI::n_mpi_processes(p.get_mpi_communicator()) == 1)
      return;
    v.update_ghost_values();
    v.set_ghost_state(false);
    ++communication().exchanges;
    communication().values += p.n_import_indices();
  }


  void
  send_ghost_parts(LevelVector &v, const VectorOperation::values operation)
  {
    const auto &p = *v.get_partitioner();
    if (Utilities::MPI::n_mpi_processes(p.get_mpi_communicator()) == 1)
      return;
    // (the ghost entries hold parts now, not copies of the owners' values)
    v.set_ghost_state(false);
    v.compress(operation);
    ++communication().exchanges;
    communication().values += p.n_ghost_indices();
  }


  void
  exchange(const MPI_Comm                                                    comm,
           const int                                                         tag,
           const std::vector<std::pair<unsigned int, ArrayView<const double>>> &sends,
           const std::vector<std::pair<unsigned int, ArrayView<double>>> &     receives)
  {
    if (sends.empty() && receives.empty())
      return;
    std::vector<MPI_Request> requests(sends.size() + receives.size());
    unsigned int             r = 0;
    for (const auto &[rank, buffer] : receives)
      {
        const int ierr =
          MPI_Irecv(buffer.data(), buffer.size(), MPI_DOUBLE, rank, tag, comm, &requests[r++]);
        AssertThrowMPI(ierr);
      }
    for (const auto &[rank, values] : sends)
      {
        const int ierr = MPI_Isend(const_cast<double *>(values.data()),
                                   values.size(),
                                   MPI_DOUBLE,
                                   rank,
                                   tag,
                                   comm,
                                   &requests[r++]);
        AssertThrowMPI(ierr);
        communication().values += values.size();
      }
    const int ierr = MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
    AssertThrowMPI(ierr);
    ++communication().exchanges;
  }


  namespace
  {
    /**
     * Below this many rows (the coarse levels) a product is computed on
     * the calling thread: the start-up of deal.II's threaded vmult()
     * outweighs the work.
     */
    constexpr unsigned int min_rows_for_threads = 512;
  } // namespace


  void
  vmult(const SparseMatrix<double> &A,
        LevelVector &               dst,
        const LevelVector &         src,
        const bool                  update_source_ghosts)
  {
    if (update_source_ghosts)
      update_ghosts(src);
    LocalElements       out(dst);
    const LocalElements in(src);
    if (A.m() > min_rows_for_threads)
      A.vmult(out, in);
    else
      // small (coarse levels): without the start-up of the threads
      for (unsigned int i = 0; i < A.m(); ++i)
        {
          double sum = 0;
          for (auto e = A.begin(i); e != A.end(i); ++e)
            sum += e->value() * in(e->column());
          out(i) = sum;
        }
  }


  std::pair<std::vector<int>, std::vector<int>>
  byte_counts_and_offsets(const std::vector<std::uint64_t> &sizes)
  {
    const std::uint64_t int_max = std::numeric_limits<int>::max();
    std::vector<int>    counts, offsets;
    std::uint64_t       offset = 0;
    for (const auto size : sizes)
      {
        AssertThrow(size <= int_max && offset <= int_max,
                    ExcMessage("a process's part of a gathered problem, or the parts before it, "
                               "exceed the 2 GB that MPI counts in an int"));
        counts.push_back(int(size));
        offsets.push_back(int(offset));
        offset += size;
      }
    return {counts, offsets};
  }


  std::vector<unsigned int>
  owners(const Utilities::MPI::Partitioner &          partitioner,
         const std::vector<types::global_dof_index> &indices)
  {
    // the end of every process's range
    const auto range = partitioner.local_range();
    const auto ends  = Utilities::MPI::all_gather(partitioner.get_mpi_communicator(),
                                                 range.second);
    std::vector<unsigned int> result;
    result.reserve(indices.size());
    for (const auto i : indices)
      result.push_back(std::upper_bound(ends.begin(), ends.end(), i) - ends.begin());
    return result;
  }


  double
  matrix_norm_square(const SparseMatrix<double> &A, const LevelVector &x)
  {
    update_ghosts(x);
    const LocalElements x_local(x);
    const unsigned int  n_owned = x.locally_owned_size();
    double              local   = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        double row = 0;
        for (auto e = A.begin(i); e != A.end(i); ++e)
          row += e->value() * x_local(e->column());
        local += x.local_element(i) * row;
      }
    return Utilities::MPI::sum(local, x.get_mpi_communicator());
  }

  void
  eliminated_matrix(const SparseMatrix<double> &A,
                    const std::vector<bool> &   eliminated,
                    const unsigned int          n_owned,
                    SparseMatrix<double> &      M)
  {
    M.reinit(A.get_sparsity_pattern());
    // (a process without DoFs of the level has an empty matrix: nothing
    // to copy, and copy_from() requires stored entries)
    if (A.n_nonzero_elements() > 0)
      M.copy_from(A);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (auto e = M.begin(i); e != M.end(i); ++e)
        if (eliminated[i] || eliminated[e->column()])
          e->value() = (i == e->column()) ? 1. : 0.;
  }


  LevelVector
  eliminated_rhs(const SparseMatrix<double> &A,
                 const LevelVector &         b,
                 const LevelVector &         x,
                 const std::vector<bool> &   eliminated)
  {
    const unsigned int n_owned = x.locally_owned_size();
    LevelVector        rhs(b), xe(x.get_partitioner()), Axe(x.get_partitioner());
    for (unsigned int i = 0; i < n_owned; ++i)
      if (eliminated[i])
        xe.local_element(i) = x.local_element(i);
    vmult(A, Axe, xe);
    rhs -= Axe;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (eliminated[i])
        rhs.local_element(i) = x.local_element(i);
    return rhs;
  }

} // namespace FoslsContact

// deal.II's vmult kernel on the local elements of LevelVectors
template void dealii::SparseMatrix<double>::vmult(FoslsContact::LocalElements &,
                                                  const FoslsContact::LocalElements &) const;
