#include <deal.II/base/utilities.h>

#include <fosls_contact/discretization/refinement_marking.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace FoslsContact
{
  template <int dim>
  bool
  mark_for_refinement(ReplicatedTriangulation<dim> &triangulation,
                      const Vector<float> &         owned_criteria,
                      const Parameters::Adaptivity &adaptivity,
                      const types::global_dof_index n_dofs)
  {
    AssertThrow(owned_criteria.size() == triangulation.n_active_cells(),
                ExcDimensionMismatch(owned_criteria.size(), triangulation.n_active_cells()));
    // Every process holds the whole mesh and must mark the same cells: each
    // cell's criterion from its owner, summed into one vector everywhere.
    const MPI_Comm comm = triangulation.get_communicator();
    Vector<float>  criteria(owned_criteria.size());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        criteria[cell->active_cell_index()] = owned_criteria[cell->active_cell_index()];
    Utilities::MPI::sum(criteria, comm, criteria);
    // (a NaN would leave the order below undefined; the indicators of a
    // finite solution are finite. They can be negative: the contact part of
    // eta_T^2 is the product <u.n - g, sigma_nn> on the cell's contact
    // faces, slightly negative where the discrete solution makes it so;
    // such cells come last.)
    for (const float c : criteria)
      AssertThrow(std::isfinite(c),
                  ExcMessage("refinement: an error indicator that is not a finite number"));

    // The cells by decreasing criterion, and how many of them the marking
    // takes: the fewest whose criteria sum to Fraction times the total
    // (Dörfler), or ceil(Fraction N), at least one.
    const unsigned int        n = criteria.size();
    std::vector<unsigned int> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return criteria[a] > criteria[b];
    });
    unsigned int taken = 0;
    using Marking      = Parameters::Adaptivity::Marking;
    if (adaptivity.marking == Marking::bulk)
      {
        double total = 0;
        for (const unsigned int c : order)
          total += criteria[c];
        double sum = 0;
        while (taken < n && (taken == 0 || sum < adaptivity.fraction * total))
          sum += criteria[order[taken++]];
      }
    else
      taken = static_cast<unsigned int>(
        std::min<double>(n, std::max(1., std::ceil(adaptivity.fraction * n - 1e-9))));

    // Cells whose criterion is within tie_tolerance of the last one taken
    // are taken too. Two runs whose solutions agree to the solver's
    // tolerance (on different numbers of processes, say) differ in their
    // criteria in the last digits; without this they could split a group
    // of nearly equal criteria differently, and their meshes would part
    // (they still can where a criterion lies at the edge of the band, which
    // takes a difference of 0.1% between nearly equal criteria). Cells that
    // are mirror images in a symmetric scene are marked together for the
    // same reason. If the last cell taken has a criterion of zero, exactly the
    // cells taken are marked (a band around zero would take every cell
    // without error); so, too, if it is negative.
    constexpr double tie_tolerance = 1e-3;
    const double     last          = n > 0 ? criteria[order[taken - 1]] : 0.;
    if (last > 0)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (criteria[cell->active_cell_index()] >= last * (1. - tie_tolerance))
            cell->set_refine_flag();
      }
    else
      {
        std::vector<bool> take(n, false);
        for (unsigned int k = 0; k < taken; ++k)
          take[order[k]] = true;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (take[cell->active_cell_index()])
            cell->set_refine_flag();
      }
    triangulation.prepare_coarsening_and_refinement();
    if (adaptivity.max_dofs == 0)
      return true;
    unsigned int marked = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      // (the flag is a RefinementCase, 3 for a quadrilateral cut both ways)
      marked += cell->refine_flag_set() != RefinementCase<dim>::no_refinement;
    const unsigned int new_vertices = Utilities::fixed_power<dim>(3) - (1 << dim);
    const unsigned int new_faces    = dim * 3 * (1 << (dim - 1)) - 2 * dim;
    const double bound = n_dofs + double(marked) * dim * (new_vertices + new_faces);
    if (bound <= adaptivity.max_dofs)
      return true;
    for (const auto &cell : triangulation.active_cell_iterators())
      cell->clear_refine_flag();
    return false;
  }


  template bool mark_for_refinement<2>(ReplicatedTriangulation<2> &,
                                       const Vector<float> &,
                                       const Parameters::Adaptivity &,
                                       const types::global_dof_index);
  template bool mark_for_refinement<3>(ReplicatedTriangulation<3> &,
                                       const Vector<float> &,
                                       const Parameters::Adaptivity &,
                                       const types::global_dof_index);
} // namespace FoslsContact
