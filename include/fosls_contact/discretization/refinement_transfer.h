#ifndef fosls_contact_discretization_refinement_transfer_h
#define fosls_contact_discretization_refinement_transfer_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/qp/level_algebra.h>

#include <map>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Carries a function of the active mesh (Q1^d x RT0^d, Cartesian, active
   * numbering) over one adaptive refinement, onto the refined mesh: the
   * same function, since the spaces are nested.
   *
   * deal.II's SolutionTransfer prolongates with the element's reference
   * matrices, which do not know the sign an RT0 basis function takes on a face
   * whose orientation is not the standard one (the half disc's mesh has such
   * faces): the stresses it carries over are wrong there, and J of the carried
   * solution is orders of magnitude above J before (doc/performance.md,
   * "Figures behind the code"). Here the prolongation applies the parent's and
   * the child's signs (rt_signs()), as LevelTransfer does between the uniform
   * levels. On a replicated mesh (as adaptive refinement): every cell is here.
   */
  template <int dim>
  class RefinementTransfer
  {
  public:
    /** Keep the local values of @p x on every active cell, before refinement. */
    void prepare(const DoFHandler<dim> &dof_handler, const LevelVector &x);

    /**
     * After refinement and DoF distribution: the function kept by
     * prepare() in the new active numbering, into @p x (sized here).
     */
    void interpolate(const DoFHandler<dim> &                                    dof_handler,
                     const Mapping<dim> &                                       mapping,
                     const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                     LevelVector &                                              x) const;

  private:
    std::map<CellId, Vector<double>> cell_values;
  };
} // namespace FoslsContact

#endif
