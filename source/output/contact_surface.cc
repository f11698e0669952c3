#include <fosls_contact/output/contact_surface.h>

#include <limits>

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
  ContactSurface<dim>::Fields::Fields(
    const Scene<dim> &                                              scene,
    const std::map<unsigned int, typename ContactRow<dim>::Values> &rows,
    const bool                                                      friction)
    : scene(scene)
    , rows(rows)
    , friction(friction)
  {}


  template <int dim>
  std::vector<std::string>
  ContactSurface<dim>::Fields::get_names() const
  {
    std::vector<std::string> names = {"contact_pressure",
                                      "normal_displacement",
                                      "gap",
                                      "remaining_gap",
                                      "in_contact",
                                      "face_pressure"};
    if (friction)
      {
        names.insert(names.end(), dim, "slip");
        names.insert(names.end(), dim, "tangential_traction");
        names.push_back("friction_status");
      }
    return names;
  }


  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  ContactSurface<dim>::Fields::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      6, DataComponentInterpretation::component_is_scalar);
    if (friction)
      {
        interpretation.insert(interpretation.end(),
                              2 * dim,
                              DataComponentInterpretation::component_is_part_of_vector);
        interpretation.push_back(DataComponentInterpretation::component_is_scalar);
      }
    return interpretation;
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
    using Row          = ContactRow<dim>;
    const double L     = scene.scaling().length;
    const auto   cell  = inputs.template get_cell<dim>();
    const auto   face  = cell->face(inputs.get_face_number());
    for (unsigned int q = 0; q < computed.size(); ++q)
      {
        // the face's own pressure at the point: RT0's normal traction,
        // constant on the face
        const Point<dim>     x_hat = inputs.evaluation_points[q] / L;
        const Tensor<1, dim> n_o   = scene.obstacle_normal(x_hat);
        Tensor<1, dim>       u, traction;
        for (unsigned int m = 0; m < dim; ++m)
          {
            u[m] = inputs.solution_values[q][m];
            for (unsigned int k = 0; k < dim; ++k)
              traction[m] += inputs.solution_values[q][dim + m * dim + k] * inputs.normals[q][k];
          }
        computed[q][5] = -(traction * n_o);
        // the rest: contact.csv's row of the face's vertex at this point
        // (the patches have no subdivisions: the points are the face's
        // vertices, in the scene's coordinates, L times the mesh's)
        unsigned int nearest  = 0;
        double       distance = std::numeric_limits<double>::max();
        for (const unsigned int v : face->vertex_indices())
          if (const double d = inputs.evaluation_points[q].distance(L * face->vertex(v));
              d < distance)
            {
              distance = d;
              nearest  = v;
            }
        const auto row = rows.find(face->vertex_index(nearest));
        if (row != rows.end())
          {
            const auto &r  = row->second;
            computed[q][0] = -r[Row::sigma_nn];
            computed[q][1] = r[Row::u_n];
            computed[q][2] = r[Row::gap];
            computed[q][3] = r[Row::remaining_gap];
            computed[q][4] = r[Row::in_contact];
            if (friction)
              for (unsigned int c = 0; c <= 2 * dim; ++c)
                computed[q][6 + c] = r[Row::slip + c];
          }
        else
          {
            // a vertex of a contact face that is no contact vertex (it is
            // also on a Dirichlet boundary, which takes precedence): the
            // face's own values there
            const double gap = L * scene.gap().value(x_hat);
            computed[q][0]   = computed[q][5];
            computed[q][1]   = u * n_o;
            computed[q][2]   = gap;
            computed[q][3]   = gap - u * n_o;
            computed[q][4]   = 0;
            // (its tangential displacement is prescribed: it sticks)
            if (friction)
              for (unsigned int c = 0; c <= 2 * dim; ++c)
                computed[q][6 + c] = c == 2 * dim ? 1. : 0.;
          }
      }
  }

  template class ContactSurface<2>;
  template class ContactSurface<3>;
} // namespace FoslsContact
