#include <deal.II/base/mpi.templates.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fosls_contact/base/collective_error.h>
#include <fosls_contact/qp/gathered_qp.h>

#include <cstring>
#include <type_traits>

namespace FoslsContact
{
  namespace
  {
    /**
     * Every process's @p mine on process 0 (empty elsewhere), in the order
     * of the ranks, as raw bytes: Utilities::MPI::gather serializes and
     * compresses its data, a large part of the definiteness check even on
     * one process (doc/performance.md, section 6).
     */
    template <typename T>
    std::vector<std::vector<T>>
    gather_parts(const MPI_Comm comm, const std::vector<T> &mine)
    {
      static_assert(std::is_trivially_copyable_v<T>, "gather_parts sends raw bytes");
      if (Utilities::MPI::n_mpi_processes(comm) == 1)
        return {mine};
      // (every process learns every size, so that all take the same
      // decision before any of them gathers)
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      auto [counts, offsets]  = byte_counts_and_offsets(
        gather_all(comm, std::uint64_t(mine.size() * sizeof(T))));
      const int         n_mine = counts[rank];
      const std::size_t total  = std::size_t(offsets.back()) + counts.back();
      if (rank != 0)
        counts.clear(), offsets.clear();
      // (the first process's memory may run out here, between collective
      // calls: every process learns it before the next, CollectiveError)
      std::vector<char> all;
      CollectiveError::run(comm, [&]() {
        if (rank == 0)
          all.resize(total);
      });
      const int ierr = MPI_Gatherv(mine.data(), n_mine, MPI_BYTE, all.data(), counts.data(),
                                   offsets.data(), MPI_BYTE, 0, comm);
      AssertThrowMPI(ierr);
      std::vector<std::vector<T>> parts(counts.size());
      CollectiveError::run(comm, [&]() {
        for (std::size_t r = 0; r < counts.size(); ++r)
          {
            parts[r].resize(counts[r] / sizeof(T));
            // (an empty part's data() may be null, which memcpy must not
            // be given even for 0 bytes: undefined behaviour)
            if (counts[r] > 0)
              std::memcpy(parts[r].data(), all.data() + offsets[r], counts[r]);
          }
      });
      return parts;
    }
  } // namespace


  std::vector<std::array<double, 3>>
  owned_entries(const SparsityPattern &            pattern,
                const SparseMatrix<double> *       matrix,
                const Utilities::MPI::Partitioner &partitioner)
  {
    Assert(matrix == nullptr || &matrix->get_sparsity_pattern() == &pattern,
           ExcMessage("owned_entries: the matrix is not on the pattern"));
    std::vector<std::array<double, 3>> entries;
    for (unsigned int i = 0; i < partitioner.locally_owned_size(); ++i)
      {
        const double row = partitioner.local_to_global(i);
        // (the matrix's entries in its own order, instead of
        // SparseMatrix::el(), which searches the row for every entry)
        if (matrix != nullptr)
          for (auto e = matrix->begin(i); e != matrix->end(i); ++e)
            entries.push_back({{row, double(partitioner.local_to_global(e->column())), e->value()}});
        else
          for (auto e = pattern.begin(i); e != pattern.end(i); ++e)
            entries.push_back({{row, double(partitioner.local_to_global(e->column())), 0.}});
      }
    return entries;
  }


  void
  assemble_gathered_entries(const std::vector<std::vector<std::array<double, 3>>> &parts,
                            const types::global_dof_index                           n,
                            SparsityPattern &                                       pattern,
                            SparseMatrix<double> *                                  matrix)
  {
    DynamicSparsityPattern dsp(n, n);
    for (const auto &part : parts)
      for (const auto &[i, j, value] : part)
        dsp.add(types::global_dof_index(i), types::global_dof_index(j));
    pattern.copy_from(dsp);
    if (matrix == nullptr)
      return;
    matrix->reinit(pattern);
    for (const auto &part : parts)
      for (const auto &[i, j, value] : part)
        matrix->set(types::global_dof_index(i), types::global_dof_index(j), value);
  }


  std::vector<unsigned int>
  owned_roles(const std::vector<DoFRole> &role, const unsigned int n_owned)
  {
    std::vector<unsigned int> roles(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      roles[i] = static_cast<unsigned int>(role[i]);
    return roles;
  }


  std::vector<DoFRole>
  gathered_roles(const std::vector<std::vector<unsigned int>> &parts)
  {
    std::vector<DoFRole> roles;
    for (const auto &part : parts)
      for (const auto r : part)
        roles.push_back(static_cast<DoFRole>(r));
    return roles;
  }


  GatheredQP::GatheredQP(const ConstrainedQP &qp)
    : comm(qp.get_communicator())
    , holder(Utilities::MPI::this_mpi_process(comm) == 0)
  {
    const auto &p = *qp.partitioner;
    if (holder)
      serial.partitioner = serial_partitioner(p.size());
    // each process owns a contiguous range, the processes in order
    for (const auto c : Utilities::MPI::all_gather(comm, int(p.locally_owned_size())))
      {
        first.push_back(first.empty() ? 0 : first.back() + count.back());
        count.push_back(c);
      }
    auto collect = [&](const auto &mine) { return gather_parts(comm, mine); };
    const auto matrix_parts   = collect(owned_entries(qp.matrix.get_sparsity_pattern(), &qp.matrix, p));
    const auto coupling_parts = collect(owned_entries(
      qp.coupling_sparsity ? *qp.coupling_sparsity : qp.matrix.get_sparsity_pattern(), nullptr, p));
    // (the complementarity part for the definiteness check's limit of its
    // weight; none without contact)
    const auto compl_parts =
      collect(qp.matrix_compl.m() > 0 ?
                owned_entries(qp.matrix_compl.get_sparsity_pattern(), &qp.matrix_compl, p) :
                std::vector<std::array<double, 3>>());
    const auto role_parts = collect(owned_roles(qp.role, p.locally_owned_size()));
    const LevelVector b = gather(qp.rhs), fixed = gather(qp.fixed_values),
                      ub = gather(qp.upper_bounds);
    FrictionTerms friction;
    if (qp.has_friction())
      friction = {gather(qp.friction.traction_bounds),
                  gather(qp.friction.slip_weights),
                  gather(qp.friction.slip_references),
                  {}};
    // (the pairs of 3D friction in global indices, which are those of the
    // gathered problem: both entries of a pair have one owner)
    std::vector<std::vector<unsigned int>> partner_parts;
    if (qp.friction.has_pairs())
      {
        std::vector<unsigned int> mine(p.locally_owned_size(), FrictionTerms::no_partner);
        for (unsigned int i = 0; i < mine.size(); ++i)
          if (qp.friction.partner[i] != FrictionTerms::no_partner)
            mine[i] = p.local_to_global(qp.friction.partner[i]);
        partner_parts = collect(mine);
      }
    // (an error of the holder alone, its memory, stops every process)
    CollectiveError::run(comm, [&]() {
      if (!holder)
        return;
      const auto n = p.size();
      assemble_gathered_entries(matrix_parts, n, serial.sparsity, &serial.matrix);
      assemble_gathered_entries(coupling_parts, n, coupling, nullptr);
      assemble_gathered_entries(compl_parts, n, serial.sparsity_compl, &serial.matrix_compl);
      serial.coupling_sparsity = &coupling;
      serial.rhs               = b;
      serial.fixed_values      = fixed;
      serial.upper_bounds      = ub;
      serial.friction          = friction;
      for (const auto &part : partner_parts)
        serial.friction.partner.insert(serial.friction.partner.end(), part.begin(), part.end());
      serial.constant          = qp.constant;
      serial.dimension         = qp.dimension;
      serial.role              = gathered_roles(role_parts);
    });
  }


  LevelVector
  GatheredQP::gather(const LevelVector &x) const
  {
    const std::vector<double> mine(x.begin(), x.begin() + x.locally_owned_size());
    const auto  all = gather_parts(comm, mine);
    LevelVector whole;
    CollectiveError::run(comm, [&]() {
      if (!holder)
        return;
      whole.reinit(serial.partitioner);
      unsigned int k = 0;
      for (const auto &part : all)
        for (const double value : part)
          whole.local_element(k++) = value;
    });
    return whole;
  }


  void
  GatheredQP::scatter(const LevelVector &whole, LevelVector &x) const
  {
    const int ierr = MPI_Scatterv(Utilities::MPI::this_mpi_process(comm) == 0 ? whole.begin() : nullptr,
                                  count.data(),
                                  first.data(),
                                  MPI_DOUBLE,
                                  x.begin(),
                                  x.locally_owned_size(),
                                  MPI_DOUBLE,
                                  0,
                                  comm);
    AssertThrowMPI(ierr);
  }
} // namespace FoslsContact
