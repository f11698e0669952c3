#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/discretization/rt_signs.h>
#include <fosls_contact/qp/matrix_list_memory.h>

namespace FoslsContact
{


  template <int dim>
  LevelTransfer<dim>::LevelTransfer(const Discretization<dim> &discretization)
  {
    RtFaceFlips<dim>   face_flips(discretization.get_mapping());
    const auto &       dof_handler = discretization.get_dof_handler();
    const auto &       fe          = discretization.get_fe();
    const unsigned int n           = fe.n_dofs_per_cell();
    const unsigned int n_levels    = discretization.n_uniform_levels();
    sparsities.resize(n_levels);
    matrices.resize(n_levels);

    // One walk over the parent cells collects the entries (child DoF,
    // parent DoF, signed embedding value); a child DoF shared by several
    // children gets the same value from each, so the last one written is
    // as good as any.
    struct Entry
    {
      types::global_dof_index row, column;
      double                  value;
    };
    std::vector<types::global_dof_index> parent_dofs(n), child_dofs(n);
    // the RT face flips of the cells of level l - 1, read when they were
    // children (each cell's once, not again as a parent; `unread` where a
    // cell was not a child here)
    constexpr unsigned char    unread = 0xff;
    std::vector<unsigned char> parent_flips, child_flips;
    for (unsigned int l = 1; l < n_levels; ++l)
      {
        // (indexed by cell->index(), which is below n_raw_cells(), not below
        // n_cells(): a distributed mesh leaves unused indices; a process
        // may have no cell on level l, and n_raw_cells() no such level)
        const auto &tria = discretization.get_triangulation();
        child_flips.assign(l < tria.n_levels() ? tria.n_raw_cells(l) : 0, unread);
        const auto &           coarse = *discretization.level(l - 1).partitioner;
        const auto &           fine   = *discretization.level(l).partitioner;
        std::vector<Entry>     entries;
        DynamicSparsityPattern dsp(discretization.level(l).n_local(),
                                   discretization.level(l - 1).n_local());
        for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l - 1))
          if (cell->has_children() && Discretization<dim>::is_present(cell))
            {
              cell->get_mg_dof_indices(parent_dofs);
              for (auto &dof : parent_dofs)
                dof = coarse.global_to_local(dof);
              const auto parent_signs =
                rt_signs(fe,
                         l > 1 && parent_flips[cell->index()] != unread ?
                           parent_flips[cell->index()] :
                           face_flips(cell));
              for (unsigned int c = 0; c < cell->n_children(); ++c)
                {
                  if (!Discretization<dim>::is_present(cell->child(c)))
                    continue;
                  const FullMatrix<double> &P =
                    fe.get_prolongation_matrix(c, cell->refinement_case());
                  cell->child(c)->get_mg_dof_indices(child_dofs);
                  for (auto &dof : child_dofs)
                    dof = fine.global_to_local(dof);
                  const unsigned int flips = face_flips(cell->child(c));
                  child_flips[cell->child(c)->index()] = flips;
                  const auto child_signs = rt_signs(fe, flips);
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      if (P(i, j) != 0)
                        {
                          dsp.add(child_dofs[i], parent_dofs[j]);
                          entries.push_back({child_dofs[i],
                                             parent_dofs[j],
                                             child_signs[i] * P(i, j) * parent_signs[j]});
                        }
                }
            }
        sparsities[l] = std::make_unique<SparsityPattern>();
        sparsities[l]->copy_from(dsp);
        matrices[l] = std::make_unique<SparseMatrix<double>>(*sparsities[l]);
        for (const auto &e : entries)
          matrices[l]->set(e.row, e.column, e.value);
        std::swap(parent_flips, child_flips);
      }
  }


  template <int dim>
  void
  LevelTransfer<dim>::prolongate(const unsigned int to_level,
                                 LevelVector &      dst,
                                 const LevelVector &src) const
  {
    vmult(*matrices[to_level], dst, src);
  }

  template <int dim>
  LevelBytes
  LevelTransfer<dim>::memory_consumption() const
  {
    return matrix_list_memory_consumption(matrices, sparsities);
  }

  template class LevelTransfer<2>;
  template class LevelTransfer<3>;
} // namespace FoslsContact
