#include <fosls_contact/discretization/rt_signs.h>

namespace FoslsContact
{
  template <int dim>
  RtFaceFlips<dim>::RtFaceFlips(const Mapping<dim> &mapping)
    : rt(0)
    , fe_values(mapping, rt, face_centers(), update_values | update_inverse_jacobians)
  {}


  template <int dim>
  Quadrature<dim>
  RtFaceFlips<dim>::face_centers()
  {
    std::vector<Point<dim>> points(GeometryInfo<dim>::faces_per_cell);
    for (unsigned int f = 0; f < points.size(); ++f)
      for (unsigned int d = 0; d < dim; ++d)
        points[f][d] = (d == f / 2) ? double(f % 2) : 0.5;
    return Quadrature<dim>(points, std::vector<double>(points.size(), 1.));
  }


  template <int dim>
  unsigned int
  RtFaceFlips<dim>::operator()(const typename Triangulation<dim>::cell_iterator &cell)
  {
    fe_values.reinit(cell);
    unsigned int flips = 0;
    for (unsigned int f = 0; f < GeometryInfo<dim>::faces_per_cell; ++f)
      {
        // RT0 has one DoF per face: the shape function whose normal
        // component is 1 on face f and 0 on the others
        const unsigned int i     = rt.face_to_cell_index(0, f);
        const auto &       J_inv = fe_values.inverse_jacobian(f);
        double             reference_component = 0;
        for (unsigned int c = 0; c < dim; ++c)
          reference_component += J_inv[f / 2][c] * fe_values.shape_value_component(i, f, c);
        if (reference_component <= 0)
          flips |= 1u << f;
      }
    return flips;
  }


  template class RtFaceFlips<2>;
  template class RtFaceFlips<3>;
} // namespace FoslsContact
