#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <fosls_contact/discretization/boundary_face_conditions.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  BoundaryFaceConditions<dim>::BoundaryFaceConditions(const Scene<dim> &     scene,
                                                      const Mapping<dim> &   mapping,
                                                      const DoFHandler<dim> &dof_handler)
    : scene(scene)
    , mapping(mapping)
    , dof_handler(dof_handler)
  {}


  template <int dim>
  typename BoundaryFaceConditions<dim>::BoundaryData
  BoundaryFaceConditions<dim>::apply(const unsigned int l, LevelData<dim> &data) const
  {
    BoundaryData          boundary;
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    const QGauss<dim - 1> face_quadrature(3);
    FEFaceValues<dim>     fe_face(mapping,
                              fe,
                              face_quadrature,
                              update_values | update_normal_vectors |
                                update_quadrature_points | update_JxW_values);
    Vector<double>                       values(dim);
    std::vector<types::global_dof_index> dofs;
    (void)l;
    data.for_each_cell(dof_handler, [&](const auto &cell) {
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f))
              continue;
            const auto               face    = cell->face(f);
            const types::boundary_id id      = face->boundary_id();
            const auto &             face_rt = data.face_dofs.at(face->index());

            // RT DoF of stress row m on this face: its normal component
            // times the outward normal, at the face quadrature points.
            fe_face.reinit(cell, f);
            std::array<unsigned int, dim> local_rt;
            data.get_local_dofs(cell, dofs);
            for (unsigned int m = 0; m < dim; ++m)
              local_rt[m] = std::find(dofs.begin(), dofs.end(), face_rt[m]) - dofs.begin();
            auto normal_component = [&](const unsigned int m, const unsigned int q) {
              const FEValuesExtractors::Vector row(dim + m * dim);
              return fe_face[row].value(local_rt[m], q) * fe_face.normal_vector(q);
            };

            // Prescribed traction, component m, as the L2 projection onto
            // the face's normal-flux basis function: it is essential here.
            auto fix_traction = [&](const unsigned int m) {
              double num = 0, den = 0;
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                {
                  const double phi_n = normal_component(m, q);
                  num += scene.traction().value(fe_face.quadrature_point(q), m) *
                         phi_n * fe_face.JxW(q);
                  den += phi_n * phi_n * fe_face.JxW(q);
                }
              data.role[face_rt[m]]                       = DoFRole::fixed;
              data.fixed_values.local_element(face_rt[m]) = num / den;
            };

            if (scene.is_dirichlet(id))
              {
                const std::vector<bool> &mask = scene.dirichlet_components(id);
                for (const unsigned int v : face->vertex_indices())
                  {
                    const unsigned int vi = face->vertex_index(v);
                    auto &vertex_mask = boundary.dirichlet_vertices.try_emplace(vi).first->second;
                    scene.dirichlet_values().vector_value(face->vertex(v), values);
                    for (unsigned int k = 0; k < dim; ++k)
                      if (mask[k])
                        {
                          vertex_mask[k]                       = true;
                          const auto dof                       = data.vertex_dofs.at(vi)[k];
                          data.role[dof]                       = DoFRole::fixed;
                          data.fixed_values.local_element(dof) = values[k];
                        }
                  }
                for (unsigned int m = 0; m < dim; ++m)
                  if (!mask[m])
                    fix_traction(m);
              }
            else if (scene.is_neumann(id))
              {
                for (unsigned int m = 0; m < dim; ++m)
                  fix_traction(m);
              }
            else if (scene.is_contact(id))
              {
                for (const unsigned int v : face->vertex_indices())
                  boundary.contact_vertex_points[face->vertex_index(v)] = face->vertex(v);
                // the mean normal component of the face's basis function
                double area = 0, c = 0;
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    area += fe_face.JxW(q);
                    c += normal_component(0, q) * fe_face.JxW(q);
                    check_obstacle_normal(fe_face.quadrature_point(q), fe_face.normal_vector(q));
                  }
                bound_contact_face(data, face_rt, scene.has_friction());
                std::array<unsigned int, GeometryInfo<dim>::vertices_per_face> vertices;
                for (const unsigned int v : face->vertex_indices())
                  vertices[v] = face->vertex_index(v);
                boundary.contact_faces.push_back({static_cast<unsigned int>(face->index()),
                                                  face_rt,
                                                  face->center(),
                                                  scene.obstacle_normal(face->center()),
                                                  area,
                                                  c / area,
                                                  vertices});
              }
          }
    });
    return boundary;
  }


  template <int dim>
  void
  BoundaryFaceConditions<dim>::check_obstacle_normal(const Point<dim> &    p,
                                                     const Tensor<1, dim> &outward) const
  {
    // The constraint u.n_o <= g bounds the displacement toward the
    // obstacle: an obstacle normal into the body, or along its surface,
    // where the obstacle is near would let the body pass through it (or
    // hold it on the wrong side, where the normal's sign changes along the
    // contact boundary). Where the obstacle is far (a gap above 1% of the
    // body's size, which small-strain displacements do not close), a part
    // of the contact boundary may face away from it: the far side of a
    // half disc over a tilted plane, whose constraint never acts.
    constexpr double near = 0.01; // (dimensionless: of the reference length)
    const double     along = scene.obstacle_normal(p) * outward;
    const double     gap   = scene.gap().value(p);
    if (along > 0 || gap > near)
      return;
    const double       L = scene.scaling().length;
    std::ostringstream text;
    text << "parameter 'Data/Obstacle normal' points "
         << (along < 0 ? "into the body" : "along the body's surface") << " at ("
         << Point<dim>(p * L) << ") of the contact boundary, where the obstacle is near (gap "
         << std::setprecision(3) << gap * L
         << "; its product with the body's outward normal is " << along
         << "): it must point out of the body, toward the obstacle";
    AssertThrow(false, ExcMessage(text.str()));
  }


  template <int dim>
  void
  BoundaryFaceConditions<dim>::bound_contact_face(LevelData<dim> &                                data,
                                          const std::array<types::global_dof_index, dim> &face_rt,
                                          const bool friction)
  {
    // the tangential tractions are 0 (without friction) or bounded by the
    // slip bound (FrictionLaw sets it), the normal one (the first rotated
    // coordinate, see add_rotations()) is bounded by 0
    for (unsigned int m = 0; m < dim; ++m)
      {
        data.role[face_rt[m]]                       = friction ? DoFRole::traction : DoFRole::fixed;
        data.fixed_values.local_element(face_rt[m]) = 0;
      }
    data.role[face_rt[0]]                       = DoFRole::bounded;
    data.upper_bounds.local_element(face_rt[0]) = 0.;
  }


  template class BoundaryFaceConditions<2>;
  template class BoundaryFaceConditions<3>;
} // namespace FoslsContact
