#ifndef fosls_contact_qp_level_algebra_h
#define fosls_contact_qp_level_algebra_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/sparse_matrix.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * A vector of one level, distributed over the MPI processes: each process
   * stores the DoFs it owns and, after update_ghost_values(), copies of its
   * ghost DoFs (those of the ghost cells around its own). Local index i
   * (owned DoFs first, in global order, then the ghosts in global order) is
   * the index of every local array of the program: roles, matrices, patch
   * lists. With one process there are no ghosts and the local index is the
   * global one.
   */
  using LevelVector = LinearAlgebra::distributed::Vector<double>;

  /**
   * The local elements of a LevelVector (owned, then ghosts) seen as a
   * vector of their own, so that deal.II's SparseMatrix kernels work on the
   * local matrices of the program (square, in local indices) without a
   * copy. Has exactly what SparseMatrix::vmult needs.
   *
   * It is also how the program reads ghost entries: they are valid after
   * update_ghosts() until the owned entries change, but update_ghosts()
   * leaves the vector out of deal.II's ghost state, and deal.II's const
   * LevelVector::local_element() refuses to read a ghost entry of such a
   * vector (its debug build checks it).
   */
  class LocalElements
  {
  public:
    using value_type     = double;
    using iterator       = double *;
    using const_iterator = const double *;
    using size_type      = types::global_dof_index;

    explicit LocalElements(LevelVector &v);
    explicit LocalElements(const LevelVector &v);

    size_type size() const { return n; }
    iterator begin() { return data; }
    const_iterator begin() const { return data; }
    double
    operator()(const size_type i) const
    {
      AssertIndexRange(i, n);
      return data[i];
    }
    double &
    operator()(const size_type i)
    {
      AssertIndexRange(i, n);
      return data[i];
    }

  private:
    double *  data;
    size_type n;
  };

  /**
   * dst = A src for a local matrix @p A (rows and columns in local indices;
   * the owned rows are complete, ghost rows are complete or empty). The
   * ghost values of @p src are updated first (unless the caller knows them
   * to be valid); the owned entries of @p dst are the product, its ghost
   * entries are not valid afterwards.
   */
  void vmult(const SparseMatrix<double> &A,
             LevelVector &               dst,
             const LevelVector &         src,
             const bool                  update_source_ghosts = true);

  /** x^T A x over the owned rows, summed over the processes. */
  double matrix_norm_square(const SparseMatrix<double> &A, const LevelVector &x);

  /**
   * The system of @p A with the DoFs flagged in @p eliminated (all local
   * DoFs, owned and ghost) held at given values, eliminated symmetrically:
   * its matrix, A with their rows (the first @p n_owned, the owned ones)
   * and columns those of the identity, into @p M (reinitialized on A's
   * pattern). Solved with the right-hand side
   * of eliminated_rhs() it gives A's solution on the other DoFs and the
   * held values on these; the active set method's step and the coarse
   * solver's held factorization build it alike, so that the same set
   * gives the same bits.
   */
  void eliminated_matrix(const SparseMatrix<double> &A,
                         const std::vector<bool> &   eliminated,
                         const unsigned int          n_owned,
                         SparseMatrix<double> &      M);

  /**
   * The right-hand side of eliminated_matrix()'s system for A y = @p b
   * with y held at @p x on the DoFs flagged in @p eliminated: b - A x_E,
   * and x itself on those DoFs.
   */
  LevelVector eliminated_rhs(const SparseMatrix<double> &A,
                             const LevelVector &         b,
                             const LevelVector &         x,
                             const std::vector<bool> &   eliminated);

  /**
   * What this process sent to others point to point (ghost updates, the
   * parts of ghost entries sent to their owners, imported matrix entries,
   * parts of Galerkin rows): the number of exchanges and of values, for the
   * communication volume per cycle that summary.json reports. Counted only
   * with more than one process.
   */
  struct CommunicationCounter
  {
    std::uint64_t exchanges = 0, values = 0;
  };
  CommunicationCounter &communication();

  /**
   * @p v.update_ghost_values(), counted (communication()). The vector is
   * then marked as not ghosted: deal.II repeats the exchange after every
   * later operation (=, add, sadd, ...) on a ghosted vector, silently. Its
   * ghost entries stay valid until the owned entries change, and every
   * read of them in this program comes after an update. A copy, by = or
   * the copy constructor, has zero ghost entries; a vector handed to
   * FEValues or DataOut is updated with update_ghost_values() itself.
   */
  void update_ghosts(const LevelVector &v);
  /**
   * @p v.compress(@p operation): the ghost entries to their owners, counted
   * (communication()). Collective; does nothing with one process.
   */
  void send_ghost_parts(LevelVector &v, const VectorOperation::values operation);

  /**
   * One point-to-point exchange of doubles, counted (communication()):
   * send every (rank, values) of @p sends, receive into every (rank,
   * buffer) of @p receives (buffers sized by the caller), and wait for
   * both. The pairs of processes must agree on the sizes.
   */
  void exchange(const MPI_Comm                                                    comm,
                const int                                                         tag,
                const std::vector<std::pair<unsigned int, ArrayView<const double>>> &sends,
                const std::vector<std::pair<unsigned int, ArrayView<double>>> &     receives);

  /**
   * f(begin, end), split into subranges of at least @p grain elements run
   * by the threads if there is more than one grain and more than one
   * thread (parallel::apply_to_subranges). deal.II's function always goes
   * through tbb::parallel_for, whose start-up costs microseconds: the
   * smoother calls it once per color and sweep on every level of every
   * cycle, mostly on small ranges on the coarse levels.
   */
  template <typename Function>
  void
  for_subranges(const unsigned int begin,
                const unsigned int end,
                const Function &   f,
                const unsigned int grain)
  {
    if (end - begin <= grain || MultithreadInfo::n_threads() == 1)
      f(begin, end);
    else
      parallel::apply_to_subranges(begin, end, f, grain);
  }

  /**
   * Copy @p values of the owned DoFs to the ghost copies on the other
   * processes (entries are small integers stored as doubles: roles, flags).
   */
  template <typename T>
  void
  exchange_ghosts(const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                  std::vector<T> &                                          values)
  {
    LevelVector        v(partitioner);
    const unsigned int n_owned = partitioner->locally_owned_size();
    for (unsigned int i = 0; i < n_owned; ++i)
      v.local_element(i) = static_cast<double>(static_cast<unsigned int>(values[i]));
    update_ghosts(v);
    for (unsigned int i = n_owned; i < n_owned + partitioner->n_ghost_indices(); ++i)
      values[i] = static_cast<T>(static_cast<unsigned int>(v.local_element(i)));
  }

  namespace internal
  {
    template <typename T>
    struct IsVectorOfPlainData : std::false_type
    {};
    template <typename T>
    struct IsVectorOfPlainData<std::vector<T>>
      : std::bool_constant<std::is_trivially_copyable_v<T> && !std::is_same_v<T, bool>>
    {};
  } // namespace internal

  /**
   * The counts and displacements in bytes (MPI's int) of a gather of parts
   * of @p sizes bytes, the processes in order; throws if a count or a
   * displacement does not fit in an int. Every process that knows all
   * sizes takes the same decision.
   */
  std::pair<std::vector<int>, std::vector<int>>
  byte_counts_and_offsets(const std::vector<std::uint64_t> &sizes);

  /**
   * Utilities::MPI::all_gather() (@p object of every process, in the order
   * of the ranks), but without its serialization, which compresses with
   * zlib even on one process: on one process @p object itself; plain data
   * (a trivially copyable object, or a std::vector of them) as bytes with
   * MPI_Allgather(v); anything else through Utilities::MPI::all_gather().
   * (The Galerkin updates gather twice per level and the coarse
   * factorization three times, so serialization would cost the coarse
   * solves several times their time; doc/performance.md, section 3.)
   */
  template <typename T>
  std::vector<T>
  gather_all(const MPI_Comm comm, const T &object)
  {
    const unsigned int n_processes = Utilities::MPI::n_mpi_processes(comm);
    if (n_processes == 1)
      return {object};
    if constexpr (std::is_trivially_copyable_v<T>)
      {
        std::vector<T> all(n_processes);
        const int      ierr = MPI_Allgather(
          &object, sizeof(T), MPI_BYTE, all.data(), sizeof(T), MPI_BYTE, comm);
        AssertThrowMPI(ierr);
        return all;
      }
    else if constexpr (internal::IsVectorOfPlainData<T>::value)
      {
        using Element = typename T::value_type;
        // (every process sees every size, so all take the same decision
        // before any of them gathers the data)
        const auto [bytes, offsets] = byte_counts_and_offsets(
          gather_all(comm, std::uint64_t(object.size() * sizeof(Element))));
        std::vector<Element> buffer((std::size_t(offsets.back()) + bytes.back()) /
                                    sizeof(Element));
        const int            ierr = MPI_Allgatherv(object.data(),
                                        bytes[Utilities::MPI::this_mpi_process(comm)],
                                        MPI_BYTE,
                                        buffer.data(),
                                        bytes.data(),
                                        offsets.data(),
                                        MPI_BYTE,
                                        comm);
        AssertThrowMPI(ierr);
        std::vector<T> all(n_processes);
        for (unsigned int p = 0; p < n_processes; ++p)
          all[p].assign(buffer.begin() + offsets[p] / sizeof(Element),
                        buffer.begin() + (offsets[p] + bytes[p]) / sizeof(Element));
        return all;
      }
    else
      return Utilities::MPI::all_gather(comm, object);
  }

  /**
   * The process that owns each of the global @p indices (every process
   * owns a contiguous range of a level's DoFs, the processes in order).
   * Collective.
   */
  std::vector<unsigned int>
  owners(const Utilities::MPI::Partitioner &          partitioner,
         const std::vector<types::global_dof_index> &indices);

  /** The partitioner of @p n DoFs all owned by this process alone. */
  inline std::shared_ptr<const Utilities::MPI::Partitioner>
  serial_partitioner(const types::global_dof_index n)
  {
    return std::make_shared<const Utilities::MPI::Partitioner>(complete_index_set(n),
                                                                MPI_COMM_SELF);
  }
} // namespace FoslsContact

#endif
