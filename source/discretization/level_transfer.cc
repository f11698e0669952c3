#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fosls_contact/discretization/level_transfer.h>

namespace FoslsContact
{
  template <int dim>
  LevelTransfer<dim>::LevelTransfer(const Discretization<dim> &discretization)
  {
    const auto &       dof_handler = discretization.get_dof_handler();
    const auto &       fe          = discretization.get_fe();
    const unsigned int n           = fe.n_dofs_per_cell();
    const unsigned int n_levels    = discretization.n_levels();
    sparsities.resize(n_levels);
    matrices.resize(n_levels);

    std::vector<types::global_dof_index> parent_dofs(n), child_dofs(n);
    for (unsigned int l = 1; l < n_levels; ++l)
      {
        DynamicSparsityPattern dsp(dof_handler.n_dofs(l), dof_handler.n_dofs(l - 1));
        for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l - 1))
          if (cell->has_children())
            {
              cell->get_mg_dof_indices(parent_dofs);
              for (unsigned int c = 0; c < cell->n_children(); ++c)
                {
                  const FullMatrix<double> &P =
                    fe.get_prolongation_matrix(c, cell->refinement_case());
                  cell->child(c)->get_mg_dof_indices(child_dofs);
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      if (P(i, j) != 0)
                        dsp.add(child_dofs[i], parent_dofs[j]);
                }
            }
        sparsities[l] = std::make_unique<SparsityPattern>();
        sparsities[l]->copy_from(dsp);
        matrices[l] = std::make_unique<SparseMatrix<double>>(*sparsities[l]);
        for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l - 1))
          if (cell->has_children())
            {
              cell->get_mg_dof_indices(parent_dofs);
              for (unsigned int c = 0; c < cell->n_children(); ++c)
                {
                  const FullMatrix<double> &P =
                    fe.get_prolongation_matrix(c, cell->refinement_case());
                  cell->child(c)->get_mg_dof_indices(child_dofs);
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      if (P(i, j) != 0)
                        matrices[l]->set(child_dofs[i], parent_dofs[j], P(i, j));
                }
            }
      }
  }


  template <int dim>
  void
  LevelTransfer<dim>::prolongate(const unsigned int    to_level,
                                 Vector<double> &      dst,
                                 const Vector<double> &src) const
  {
    matrices[to_level]->vmult(dst, src);
  }

  template class LevelTransfer<2>;
  template class LevelTransfer<3>;
} // namespace FoslsContact
