#include <fosls_contact/output/contact_surface.h>

namespace FoslsContact
{
  template <int dim>
  ContactSurface<dim>::ContactSurface(const Scene<dim> &scene)
    : DataOutFaces<dim>(true)
    , scene(scene)
  {}


  template <int dim>
  typename ContactSurface<dim>::FaceDescriptor
  ContactSurface<dim>::find(typename Triangulation<dim>::active_cell_iterator cell,
                            unsigned int                                      f) const
  {
    const auto end = this->triangulation->end();
    for (; cell != end; ++cell, f = 0)
      if (cell->is_locally_owned())
        for (; f < cell->n_faces(); ++f)
          if (cell->at_boundary(f) && scene.is_contact(cell->face(f)->boundary_id()))
            return FaceDescriptor(cell, f);
    return FaceDescriptor(end, 0);
  }


  template <int dim>
  typename ContactSurface<dim>::FaceDescriptor
  ContactSurface<dim>::first_face()
  {
    return find(this->triangulation->begin_active(), 0);
  }


  template <int dim>
  typename ContactSurface<dim>::FaceDescriptor
  ContactSurface<dim>::next_face(const FaceDescriptor &face)
  {
    return find(typename Triangulation<dim>::active_cell_iterator(face.first), face.second + 1);
  }


  template <int dim>
  ContactSurface<dim>::Fields::Fields(const Scene<dim> &scene)
    : scene(scene)
  {}


  template <int dim>
  std::vector<std::string>
  ContactSurface<dim>::Fields::get_names() const
  {
    return {"contact_pressure", "normal_displacement", "gap"};
  }


  template <int dim>
  UpdateFlags
  ContactSurface<dim>::Fields::get_needed_update_flags() const
  {
    return update_values | update_normal_vectors | update_quadrature_points;
  }


  template <int dim>
  void
  ContactSurface<dim>::Fields::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>> &               computed) const
  {
    const double L = scene.scaling().length;
    for (unsigned int q = 0; q < computed.size(); ++q)
      {
        // the scene's functions are dimensionless at dimensionless points
        const Point<dim>     x_hat = inputs.evaluation_points[q] / L;
        const Tensor<1, dim> n_o   = scene.obstacle_normal(x_hat);
        Tensor<1, dim>       u, traction;
        for (unsigned int m = 0; m < dim; ++m)
          {
            u[m] = inputs.solution_values[q][m];
            for (unsigned int k = 0; k < dim; ++k)
              traction[m] += inputs.solution_values[q][dim + m * dim + k] * inputs.normals[q][k];
          }
        computed[q][0] = -(traction * n_o);
        computed[q][1] = u * n_o;
        computed[q][2] = L * scene.gap().value(x_hat) - u * n_o;
      }
  }

  template class ContactSurface<2>;
  template class ContactSurface<3>;
} // namespace FoslsContact
