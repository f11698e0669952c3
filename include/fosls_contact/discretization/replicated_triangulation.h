#ifndef fosls_contact_discretization_replicated_triangulation_h
#define fosls_contact_discretization_replicated_triangulation_h

#include <deal.II/distributed/shared_tria.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * A mesh that every process holds whole, with multigrid levels and no
   * artificial cell: each cell, active or not, is owned by one process
   * (Z-order partition) and is a ghost of all others.
   *
   * deal.II 9.4 builds the multigrid levels of a
   * parallel::shared::Triangulation only with artificial cells (the
   * constructor refuses construct_multigrid_hierarchy without them): cells
   * away from a process's own are marked artificial on it and get no DoFs
   * there. The adaptive hierarchy needs them all (Discretization), so after
   * every partition (creation, copy, refinement) this class gives each cell its
   * true owner back, on the active mesh and on every level: the DoF
   * handler then distributes the DoFs of every cell on every process, and
   * the relevant DoFs are all DoFs.
   *
   * The triangulation's number cache is left as deal.II computed it, with
   * the artificial cells: the ghost owners (active and by level) are the
   * neighbours of the partition's halo, and the cells that were artificial
   * have no global active or level cell index (nor a place in the active
   * cell index partitioner). Computing it again would make the ghost
   * owners one-sided where a process owns no cell of a level (a coarse
   * mesh of one cell on two processes), which deal.II's debug build checks
   * by a pairwise exchange that then waits forever. Nothing in this
   * program reads these fields; the deal.II functions it uses on this mesh
   * (the DoF handler's distribution, extract_locally_relevant_(level_)dofs,
   * make_hanging_node_constraints, DataOut) look at the subdomain ids
   * only. deal.II features that read them (MGTransferMatrixFree,
   * MatrixFree, CellDataTransfer, GridTools::exchange_cell_data_to_ghosts)
   * would need the cache computed for the whole mesh.
   */
  template <int dim>
  class ReplicatedTriangulation : public parallel::shared::Triangulation<dim>
  {
  public:
    using Base = parallel::shared::Triangulation<dim>;

    ReplicatedTriangulation(const MPI_Comm                                   comm,
                            const typename Triangulation<dim>::MeshSmoothing smoothing);

    // (the other overloads as the base class has them)
    using Base::create_triangulation;

    void
    create_triangulation(const std::vector<Point<dim>> &   vertices,
                         const std::vector<CellData<dim>> &cells,
                         const SubCellData &                subcell_data) override;

    void copy_triangulation(const Triangulation<dim> &other) override;

    void execute_coarsening_and_refinement() override;

  private:
    /** Every cell's true owner back, active and on every level. */
    void restore_owners();
  };
} // namespace FoslsContact

#endif
