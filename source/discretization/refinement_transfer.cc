
#include <fosls_contact/discretization/refinement_transfer.h>
#include <fosls_contact/discretization/rt_signs.h>

namespace FoslsContact
{
  template <int dim>
  void
  RefinementTransfer<dim>::prepare(const DoFHandler<dim> &dof_handler, const LevelVector &x)
  {
    cell_values.clear();
    Vector<double> local(dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_values(x, local);
          cell_values[cell->id()] = local;
        }
  }


  template <int dim>
  void
  RefinementTransfer<dim>::interpolate(
    const DoFHandler<dim> &                                    dof_handler,
    const Mapping<dim> &                                       mapping,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
    LevelVector &                                              x) const
  {
    const auto &       fe = dof_handler.get_fe();
    const unsigned int n  = fe.n_dofs_per_cell();
    x.reinit(partitioner);
    RtFaceFlips<dim>  face_flips(mapping);
    Vector<double>    parent_local(n), local(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        const auto kept = cell_values.find(cell->id());
        if (kept != cell_values.end())
          {
            cell->set_dof_values(kept->second, x);
            continue;
          }
        // a child of a cell refined now: the parent's values prolongated,
        // with the RT signs of both (as LevelTransfer does between levels)
        const auto parent = cell->parent();
        const auto from   = cell_values.find(parent->id());
        AssertThrow(from != cell_values.end(),
                    ExcMessage("RefinementTransfer: a cell refined more than once"));
        const auto parent_signs = rt_signs(fe, face_flips(parent));
        const auto child_signs  = rt_signs(fe, face_flips(cell));
        for (unsigned int j = 0; j < n; ++j)
          parent_local[j] = parent_signs[j] * from->second[j];
        fe.get_prolongation_matrix(parent->child_iterator_to_index(cell), parent->refinement_case())
          .vmult(local, parent_local);
        for (unsigned int i = 0; i < n; ++i)
          local[i] *= child_signs[i];
        cell->set_dof_values(local, x);
      }
  }


  template class RefinementTransfer<2>;
  template class RefinementTransfer<3>;
} // namespace FoslsContact
