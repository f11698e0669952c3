#include <fosls_contact/qp/sparse_round_off.h>
#include <fosls_contact/solvers/level_truncation.h>

#include <limits>

namespace FoslsContact
{
  void
  LevelTruncation::prepare(const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                           const SparseMatrix<double> &                              A,
                           const Version                                             version,
                           const std::vector<DoFRole> &                              role)
  {
    const unsigned int n_local = partitioner->locally_owned_size() + partitioner->n_ghost_indices();
    if (defect.get_partitioner() != partitioner)
      {
        truncated_dofs.resize(n_local);
        defect.reinit(partitioner);
      }
    const bool new_operator = operator_version != version;
    if (new_operator)
      {
        // (the same on every process: the diagonal has ghost values)
        diagonal_values = diagonal(A, partitioner);
        update_ghosts(diagonal_values); // (an assignment copies the owned entries only)
      }
    if (new_operator || roles != role)
      {
        fixed_truncated.resize(n_local);
        bounded_dofs.clear();
        for (unsigned int i = 0; i < n_local; ++i)
          {
            fixed_truncated[i] =
              role[i] == DoFRole::fixed || diagonal_values.local_element(i) <= 0;
            if (role[i] == DoFRole::bounded && !fixed_truncated[i])
              bounded_dofs.push_back(i);
            defect.local_element(i) = std::numeric_limits<double>::infinity();
          }
        operator_version = version;
        roles            = role;
      }
  }


  void
  LevelTruncation::truncate(const LevelVector &ub, const LevelVector &v)
  {
    truncated_dofs = fixed_truncated;
    // (bounded_dofs has ghost DoFs, whose entries the caller has updated:
    // see LocalElements)
    const LocalElements v_local(v), ub_local(ub);
    for (const auto i : bounded_dofs)
      {
        const double vi = v_local(i), ubi = ub_local(i);
        truncated_dofs[i] = vi >= ubi; // active
        defect.local_element(i) =
          truncated_dofs[i] ? std::numeric_limits<double>::infinity() : ubi - vi;
      }
  }
} // namespace FoslsContact
