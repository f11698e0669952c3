#include <fosls_contact/scene/physical_mapping.h>

namespace FoslsContact
{
  template <int dim>
  PhysicalMapping<dim>::PhysicalMapping(const unsigned int degree, const double length)
    : MappingQ<dim>(degree)
    , length(length)
  {}


  template <int dim>
  std::unique_ptr<Mapping<dim>>
  PhysicalMapping<dim>::clone() const
  {
    return std::make_unique<PhysicalMapping<dim>>(*this);
  }


  template <int dim>
  bool
  PhysicalMapping<dim>::preserves_vertex_locations() const
  {
    return length == 1.;
  }


  template <int dim>
  boost::container::small_vector<Point<dim>, GeometryInfo<dim>::vertices_per_cell>
  PhysicalMapping<dim>::get_vertices(const typename Triangulation<dim>::cell_iterator &cell) const
  {
    auto vertices = Mapping<dim>::get_vertices(cell);
    for (auto &v : vertices)
      v *= length;
    return vertices;
  }


  template <int dim>
  std::vector<Point<dim>>
  PhysicalMapping<dim>::compute_mapping_support_points(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    auto points = MappingQ<dim>::compute_mapping_support_points(cell);
    for (auto &p : points)
      p *= length;
    return points;
  }

  template class PhysicalMapping<2>;
  template class PhysicalMapping<3>;
} // namespace FoslsContact
