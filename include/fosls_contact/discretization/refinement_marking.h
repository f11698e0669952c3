#ifndef fosls_contact_discretization_refinement_marking_h
#define fosls_contact_discretization_refinement_marking_h

#include <deal.II/lac/vector.h>

#include <fosls_contact/discretization/replicated_triangulation.h>
#include <fosls_contact/parameters/adaptivity.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Mark the active cells of @p triangulation, a mesh that every process
   * holds whole, for refinement by @p criteria (one entry per active cell,
   * the owned ones set: eta_T^2; every process marks every cell alike) as
   * Adaptivity/Marking and Fraction say: Dörfler's bulk criterion (the
   * fewest cells of the largest eta_T whose eta_T^2 sum to Fraction times
   * the total) or a fixed fraction (the ceil(Fraction N) cells of the
   * largest eta_T), at least one cell, and with them every cell whose
   * eta_T^2 is within 0.1% of the smallest one taken if that is positive
   * (see the source for why); then the marks that the mesh's smoothing
   * (at most one level of difference at a vertex) adds. Nothing is
   * coarsened.
   * Returns false, with no cell marked, if the refined mesh could have more
   * than Adaptivity/Max DoFs DoFs, from @p n_dofs now: a bound, not an
   * estimate (refining a cell adds at most 3^d - 2^d vertices and
   * 3 d 2^(d-1) - 2 d faces, those of its children less its own, each with
   * d DoFs, fewer where neighbours share them). Collective.
   */
  template <int dim>
  bool
  mark_for_refinement(ReplicatedTriangulation<dim> &triangulation,
                      const Vector<float> &         criteria,
                      const Parameters::Adaptivity &adaptivity,
                      const types::global_dof_index n_dofs);
} // namespace FoslsContact

#endif
