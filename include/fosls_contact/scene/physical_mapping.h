#ifndef fosls_contact_scene_physical_mapping_h
#define fosls_contact_scene_physical_mapping_h

#include <deal.II/fe/mapping_q.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The mapping of the dimensionless mesh (ReferenceScales) onto the scene's
   * coordinates, x = L x^: a MappingQ whose support points are scaled by
   * L. Everything that reports values in the scene's units integrates and
   * writes with it (Postprocessor), so the VTU shows the body where the
   * scene put it, and gradients, normals and areas are those of the
   * scene's units. With it, a finite element vector represents a field
   * in the scene's units when its displacement DoFs (nodal values) are
   * multiplied by L and its Raviart-Thomas DoFs (fluxes through faces of
   * size L^(dim-1) times the dimensionless ones) by S L^(dim-1).
   */
  template <int dim>
  class PhysicalMapping : public MappingQ<dim>
  {
  public:
    PhysicalMapping(const unsigned int degree, const double length);
    PhysicalMapping(const PhysicalMapping<dim> &) = default;

    std::unique_ptr<Mapping<dim>> clone() const override;
    /** The scaled vertices are not the triangulation's (unless L = 1). */
    bool preserves_vertex_locations() const override;
    boost::container::small_vector<Point<dim>, GeometryInfo<dim>::vertices_per_cell>
    get_vertices(const typename Triangulation<dim>::cell_iterator &cell) const override;

  protected:
    std::vector<Point<dim>> compute_mapping_support_points(
      const typename Triangulation<dim>::cell_iterator &cell) const override;

  private:
    const double length;
  };
} // namespace FoslsContact

#endif
