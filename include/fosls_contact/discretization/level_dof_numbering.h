#ifndef fosls_contact_discretization_level_dof_numbering_h
#define fosls_contact_discretization_level_dof_numbering_h

#include <deal.II/dofs/dof_handler.h>

#include <array>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The order of the level DoFs by geometry: their support points, base
   * element and component. The patch smoother's memory access and the
   * sweep of projected Gauss-Seidel depend on the order of the DoFs, and a
   * geometric order is the same on any number of processes where p4est's
   * is not; this class is where that order is made.
   */
  template <int dim>
  class LevelDoFNumbering
  {
  public:
    LevelDoFNumbering(const DoFHandler<dim> &dof_handler);

    /**
     * The new numbers (for DoFHandler::renumber_dofs()) that number the
     * DoFs of level @p l, within each process's owned range, in the order
     * of owned_dof_keys(). The patch smoother sweeps the
     * vertices of one kind in that order (MultilevelHierarchy:
     * VertexKey), so the values a patch gathers and those of the next
     * patches lie next to each other in memory; p4est numbers them in the
     * cells' Z-order, which puts a vertex's neighbours above and below it
     * far apart. With one process this numbering is the order of the keys
     * over the whole level; with several, each process's range is, so the
     * numbering depends on the partition (see sweep_order()).
     */
    std::vector<types::global_dof_index> level_renumbering(const unsigned int l) const;
    /**
     * The DoFs of level @p l in the order of their support points, base
     * element and component over all processes (the numbering of one
     * process): on process 0 their global indices in that order, empty
     * elsewhere. A method that sweeps in this order does the same on any
     * number of processes (ProjectedGaussSeidel). Collective.
     */
    std::vector<types::global_dof_index> sweep_order(const unsigned int l) const;

  private:
    /**
     * The owned DoFs of level @p l sorted by their keys: the position of
     * the support point (the vertex, the face center; x first), the base
     * element and the component (dim + 2 numbers), followed by the DoF's
     * global index. The keys are geometry only, so the same on any number
     * of processes.
     */
    std::vector<std::array<double, dim + 3>> owned_dof_keys(const unsigned int l) const;

    const DoFHandler<dim> &dof_handler;
  };
} // namespace FoslsContact

#endif
