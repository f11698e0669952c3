#include <deal.II/base/utilities.h>
#include <deal.II/distributed/grid_refinement.h>

#include <fosls_contact/discretization/refinement_marking.h>

#include <algorithm>
#include <cmath>

namespace FoslsContact
{
  template <int dim>
  bool
  mark_for_refinement(parallel::distributed::Triangulation<dim> &triangulation,
                      const Vector<float> &                      criteria,
                      const Parameters::Adaptivity &             adaptivity,
                      const types::global_dof_index              n_dofs)
  {
    using Marking = Parameters::Adaptivity::Marking;
    if (adaptivity.marking == Marking::bulk)
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_fraction(
        triangulation, criteria, adaptivity.fraction, 0.);
    else
      {
        // deal.II marks floor(fraction N) cells, none for a fraction below
        // 1/N, and the loop would solve on the same mesh again: mark
        // ceil(fraction N) (the half keeps the floor of the product above
        // the round-off)
        const double n      = triangulation.n_global_active_cells();
        const double marked = std::ceil(adaptivity.fraction * n - 1e-9);
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
          triangulation, criteria, std::min(1., (marked + 0.5) / n), 0.);
      }
    triangulation.prepare_coarsening_and_refinement();
    if (adaptivity.max_dofs == 0)
      return true;
    unsigned int marked = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      marked += cell->is_locally_owned() && cell->refine_flag_set();
    const unsigned int new_vertices = Utilities::fixed_power<dim>(3) - (1 << dim);
    const unsigned int new_faces    = dim * 3 * (1 << (dim - 1)) - 2 * dim;
    const double       bound =
      n_dofs + double(Utilities::MPI::sum(marked, triangulation.get_communicator())) * dim *
                 (new_vertices + new_faces);
    if (bound <= adaptivity.max_dofs)
      return true;
    for (const auto &cell : triangulation.active_cell_iterators())
      cell->clear_refine_flag();
    return false;
  }


  template bool mark_for_refinement<2>(parallel::distributed::Triangulation<2> &,
                                       const Vector<float> &,
                                       const Parameters::Adaptivity &,
                                       const types::global_dof_index);
  template bool mark_for_refinement<3>(parallel::distributed::Triangulation<3> &,
                                       const Vector<float> &,
                                       const Parameters::Adaptivity &,
                                       const types::global_dof_index);
} // namespace FoslsContact
