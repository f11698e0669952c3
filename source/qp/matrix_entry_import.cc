#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>

#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/qp/matrix_entry_import.h>

#include <map>

namespace FoslsContact
{
  void
  MatrixEntryImport::reinit(const std::vector<Entry> &                                 requests,
                            const SparsityPattern &                                    pattern,
                            const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                            const bool zero_if_missing)
  {
    comm = partitioner->get_mpi_communicator();
    requests_local.clear();
    receives.clear();
    sends.clear();
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      {
        AssertThrow(requests.empty(),
                    ExcMessage("MatrixEntryImport: requests on a single process"));
        return;
      }

    // the owner of every requested row
    std::vector<types::global_dof_index> rows;
    for (const auto &r : requests)
      rows.push_back(r.first);
    const std::vector<unsigned int> owner = owners(*partitioner, rows);

    std::map<unsigned int, std::vector<types::global_dof_index>> asked;
    std::map<unsigned int, std::vector<unsigned int>>            asked_index;
    for (unsigned int k = 0; k < requests.size(); ++k)
      {
        AssertThrow(owner[k] != Utilities::MPI::this_mpi_process(comm),
                    ExcMessage("MatrixEntryImport: a requested row is owned here"));
        asked[owner[k]].push_back(requests[k].first);
        asked[owner[k]].push_back(requests[k].second);
        asked_index[owner[k]].push_back(k);
        requests_local.emplace_back(partitioner->global_to_local(requests[k].first),
                                    partitioner->global_to_local(requests[k].second));
      }
    for (const auto &[rank, index] : asked_index)
      receives.emplace_back(rank, index);

    const std::map<unsigned int, std::vector<types::global_dof_index>> questions =
      Utilities::MPI::some_to_some(comm, asked);
    for (const auto &[rank, list] : questions)
      {
        std::vector<std::pair<unsigned int, unsigned int>> entries;
        for (unsigned int k = 0; k + 1 < list.size(); k += 2)
          {
            AssertThrow(partitioner->in_local_range(list[k]) &&
                          (partitioner->is_ghost_entry(list[k + 1]) ||
                           partitioner->in_local_range(list[k + 1])),
                        ExcMessage("MatrixEntryImport: an entry outside the ghost layer"));
            const unsigned int row = partitioner->global_to_local(list[k]);
            const unsigned int col = partitioner->global_to_local(list[k + 1]);
            AssertThrow(zero_if_missing || pattern.exists(row, col),
                        ExcMessage("MatrixEntryImport: a requested entry is not in "
                                   "the owner's pattern"));
            entries.emplace_back(row, col);
          }
        sends.emplace_back(rank, entries);
      }
  }


  void
  MatrixEntryImport::import(const SparseMatrix<double> &matrix,
                            std::vector<double> &       values) const
  {
    values.resize(requests_local.size());
    if (receives.empty() && sends.empty())
      return;
    std::vector<std::vector<double>> send_buffers(sends.size()), receive_buffers(receives.size());
    std::vector<std::pair<unsigned int, ArrayView<const double>>> to;
    std::vector<std::pair<unsigned int, ArrayView<double>>>       from;
    for (unsigned int s = 0; s < sends.size(); ++s)
      {
        for (const auto &[row, col] : sends[s].second)
          send_buffers[s].push_back(matrix.el(row, col));
        to.emplace_back(sends[s].first, make_array_view(send_buffers[s]));
      }
    for (unsigned int s = 0; s < receives.size(); ++s)
      {
        receive_buffers[s].resize(receives[s].second.size());
        from.emplace_back(receives[s].first, make_array_view(receive_buffers[s]));
      }
    exchange(comm, 4711, to, from);
    for (unsigned int s = 0; s < receives.size(); ++s)
      for (unsigned int k = 0; k < receives[s].second.size(); ++k)
        values[receives[s].second[k]] = receive_buffers[s][k];
  }


  void
  MatrixEntryImport::import_into(SparseMatrix<double> &matrix) const
  {
    std::vector<double> values;
    import(matrix, values);
    for (unsigned int k = 0; k < requests_local.size(); ++k)
      matrix.set(requests_local[k].first, requests_local[k].second, values[k]);
  }
} // namespace FoslsContact
