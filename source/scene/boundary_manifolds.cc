#include <deal.II/grid/manifold_lib.h>

#include <fosls_contact/scene/boundary_manifolds.h>

#include <cmath>
#include <set>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    // (CylindricalManifold exists in 3D only; Parameters refuses a
    // cylinder in 2D)
    void
    set_cylinder(Triangulation<2> &, const types::manifold_id, const Tensor<1, 2> &, const Point<2> &)
    {
      Assert(false, ExcInternalError());
    }

    void
    set_cylinder(Triangulation<3> &       tria,
                 const types::manifold_id id,
                 const Tensor<1, 3> &     direction,
                 const Point<3> &         point)
    {
      tria.set_manifold(id, CylindricalManifold<3>(direction, point));
    }
  } // namespace


  template <int dim>
  BoundaryManifolds<dim>::BoundaryManifolds(
    const std::vector<Parameters::Geometry::Manifold> &manifolds,
    const double                                       length)
    : manifolds(manifolds)
    , length(length)
  {}


  template <int dim>
  double
  BoundaryManifolds<dim>::distance(const Parameters::Geometry::Manifold &m,
                                   const Point<dim> &                    p) const
  {
    Tensor<1, dim> v;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] = p[d] * length - m.point[d];
    if (m.kind == Parameters::Geometry::Manifold::Kind::cylinder)
      {
        Tensor<1, dim> axis;
        for (unsigned int d = 0; d < dim; ++d)
          axis[d] = m.direction[d];
        axis /= axis.norm();
        v -= (v * axis) * axis;
      }
    return std::abs(v.norm() - m.radius) / m.radius;
  }


  template <int dim>
  void
  BoundaryManifolds<dim>::attach(Triangulation<dim> &tria, const std::string &mesh) const
  {
    for (const auto &m : manifolds)
      {
        const std::string entry =
          "parameter 'Geometry/Manifolds' has entry '" + Utilities::trim(m.text) + "'";
        bool       found    = false;
        double     farthest = 0;
        Point<dim> vertex;
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == m.boundary_id)
              {
                found = true;
                for (const unsigned int v : face->vertex_indices())
                  if (distance(m, face->vertex(v)) > farthest)
                    {
                      farthest = distance(m, face->vertex(v));
                      vertex   = face->vertex(v);
                    }
                face->set_all_manifold_ids(m.boundary_id);
              }
        if (!found)
          {
            std::string ids;
            for (const auto id : tria.get_boundary_ids())
              ids += (ids.empty() ? "" : ", ") + std::to_string(id);
            AssertThrow(false,
                        ExcMessage(entry + ", but " + mesh + " has no boundary id " +
                                   std::to_string(m.boundary_id) + " (its boundary ids: " + ids +
                                   ")"));
          }
        if (farthest > 1e-3)
          {
            std::ostringstream text;
            text << entry << ": the vertex (";
            for (unsigned int d = 0; d < dim; ++d)
              text << (d ? ", " : "") << vertex[d] * length;
            text << ") of boundary id " << m.boundary_id << " of " << mesh << " lies "
                 << farthest * m.radius << " off the "
                 << (m.kind == Parameters::Geometry::Manifold::Kind::sphere ? "sphere" : "cylinder")
                 << " (more than 1e-3 of its radius)";
            AssertThrow(false, ExcMessage(text.str()));
          }
        Point<dim> point;
        for (unsigned int d = 0; d < dim; ++d)
          point[d] = m.point[d] / length;
        if (m.kind == Parameters::Geometry::Manifold::Kind::sphere)
          tria.set_manifold(m.boundary_id, SphericalManifold<dim>(point));
        else
          {
            Tensor<1, dim> direction;
            for (unsigned int d = 0; d < dim; ++d)
              direction[d] = m.direction[d];
            set_cylinder(tria, m.boundary_id, direction / direction.norm(), point);
          }
      }
  }

  template class BoundaryManifolds<2>;
  template class BoundaryManifolds<3>;
} // namespace FoslsContact
