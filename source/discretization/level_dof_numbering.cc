#include <fosls_contact/discretization/level_data.h>
#include <fosls_contact/discretization/level_dof_numbering.h>

#include <algorithm>

namespace FoslsContact
{
  template <int dim>
  LevelDoFNumbering<dim>::LevelDoFNumbering(const DoFHandler<dim> &dof_handler)
    : dof_handler(dof_handler)
  {}


  template <int dim>
  std::vector<std::array<double, dim + 3>>
  LevelDoFNumbering<dim>::owned_dof_keys(const unsigned int l) const
  {
    const IndexSet &                         owned = dof_handler.locally_owned_mg_dofs(l);
    std::vector<std::array<double, dim + 3>> keys;
    std::vector<bool>                        seen(owned.n_elements(), false);
    std::vector<types::global_dof_index>     dofs(dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(l))
      if (level_cell_is_present(cell))
        {
          cell->get_mg_dof_indices(dofs);
          for (unsigned int i = 0; i < dof_handler.get_fe().n_dofs_per_cell(); ++i)
            if (owned.is_element(dofs[i]) && !seen[owned.index_within_set(dofs[i])])
              {
                seen[owned.index_within_set(dofs[i])] = true;
                const auto       base  = dof_handler.get_fe().system_to_base_index(i);
                const Point<dim> point = base.first.first == 0 ?
                                           cell->vertex(base.second) :
                                           cell->face(base.second)->center();
                std::array<double, dim + 3> key;
                for (unsigned int d = 0; d < dim; ++d)
                  key[d] = point[d];
                key[dim]     = base.first.first;
                key[dim + 1] = base.first.second;
                key[dim + 2] = dofs[i];
                keys.push_back(key);
              }
        }
    AssertThrow(keys.size() == owned.n_elements(),
                ExcMessage("Discretization: an owned DoF without a cell here"));
    std::sort(keys.begin(), keys.end());
    return keys;
  }


  template <int dim>
  std::vector<types::global_dof_index>
  LevelDoFNumbering<dim>::level_renumbering(const unsigned int l) const
  {
    // (the gain is in the cache: about 6-8% less time per cycle per DoF
    // on the square's levels 8 and 9, none measurable on the small levels;
    // bench/compare.py against p4est's numbering)
    const IndexSet &                     owned = dof_handler.locally_owned_mg_dofs(l);
    const auto                           keys  = owned_dof_keys(l);
    std::vector<types::global_dof_index> new_numbers(owned.n_elements());
    for (unsigned int k = 0; k < keys.size(); ++k)
      new_numbers[owned.index_within_set(types::global_dof_index(keys[k][dim + 2]))] =
        owned.nth_index_in_set(k);
    return new_numbers;
  }


  template <int dim>
  std::vector<types::global_dof_index>
  LevelDoFNumbering<dim>::sweep_order(const unsigned int l) const
  {
    std::vector<double> mine;
    for (const auto &key : owned_dof_keys(l))
      mine.insert(mine.end(), key.begin(), key.end());
    const auto all = Utilities::MPI::gather(dof_handler.get_communicator(), mine, 0);
    std::vector<std::array<double, dim + 3>> keys;
    for (const auto &part : all)
      for (std::size_t k = 0; k < part.size(); k += dim + 3)
        {
          keys.emplace_back();
          std::copy(part.begin() + k, part.begin() + k + dim + 3, keys.back().begin());
        }
    std::sort(keys.begin(), keys.end());
    std::vector<types::global_dof_index> order;
    for (const auto &key : keys)
      order.push_back(types::global_dof_index(key[dim + 2]));
    return order;
  }


  template class LevelDoFNumbering<2>;
  template class LevelDoFNumbering<3>;
} // namespace FoslsContact
