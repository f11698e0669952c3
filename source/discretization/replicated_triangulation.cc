#include <fosls_contact/discretization/replicated_triangulation.h>

namespace FoslsContact
{
  template <int dim>
  ReplicatedTriangulation<dim>::ReplicatedTriangulation(
    const MPI_Comm                                   comm,
    const typename Triangulation<dim>::MeshSmoothing smoothing)
    // (Z-order: a partition that depends on the mesh only, not on a graph
    // partitioner's library)
    : Base(comm,
           smoothing,
           true,
           typename Base::Settings(Base::partition_zorder | Base::construct_multigrid_hierarchy))
  {}


  template <int dim>
  void
  ReplicatedTriangulation<dim>::create_triangulation(const std::vector<Point<dim>> &   vertices,
                                                     const std::vector<CellData<dim>> &cells,
                                                     const SubCellData &subcell_data)
  {
    Base::create_triangulation(vertices, cells, subcell_data);
    restore_owners();
  }


  template <int dim>
  void
  ReplicatedTriangulation<dim>::copy_triangulation(const Triangulation<dim> &other)
  {
    Base::copy_triangulation(other);
    restore_owners();
  }


  template <int dim>
  void
  ReplicatedTriangulation<dim>::execute_coarsening_and_refinement()
  {
    Base::execute_coarsening_and_refinement();
    restore_owners();
  }


  template <int dim>
  void
  ReplicatedTriangulation<dim>::restore_owners()
  {
    const std::vector<types::subdomain_id> &owners = this->get_true_subdomain_ids_of_cells();
    for (const auto &cell : this->active_cell_iterators())
      cell->set_subdomain_id(owners[cell->active_cell_index()]);
    // (deal.II fills a level's owners in the order of its cells, not by
    // cell index: the two part where a level has unused cells)
    for (unsigned int l = 0; l < this->n_levels(); ++l)
      {
        const std::vector<types::subdomain_id> &level_owners =
          this->get_true_level_subdomain_ids_of_cells(l);
        AssertThrow(level_owners.size() == this->n_cells(l),
                    ExcMessage("ReplicatedTriangulation: no owner for every cell of a level"));
        unsigned int k = 0;
        for (const auto &cell : this->cell_iterators_on_level(l))
          cell->set_level_subdomain_id(level_owners[k++]);
      }
  }


  template class ReplicatedTriangulation<2>;
  template class ReplicatedTriangulation<3>;
} // namespace FoslsContact
