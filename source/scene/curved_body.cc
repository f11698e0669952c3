#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <fosls_contact/scene/curved_body.h>

#include <cmath>

namespace FoslsContact
{
  namespace
  {
    /**
     * The grading of a point at distance @p r from the center and at the
     * angle @p theta from the downward direction: the angle and the distance
     * to the curved boundary raised to the power @p gamma (1: unchanged).
     */
    std::pair<double, double>
    graded(const double r, const double theta, const double radius, const double gamma)
    {
      const double half_pi = numbers::PI / 2;
      const double t       = std::abs(theta) / half_pi;
      const double theta_g = (theta < 0 ? -1. : 1.) * half_pi * std::pow(t, gamma);
      const double s       = std::max(0., 1. - r / radius);
      return {radius * (1. - std::pow(s, gamma)), theta_g};
    }

    /**
     * deal.II's half ball of @p radius around the origin (in 2D the half
     * disc; cut plane perpendicular to x, the body at x >= 0), refined
     * @p refinements times and flattened into a coarse mesh of useful size.
     */
    template <int dim>
    void
    refined_half_ball(const double radius, const unsigned int refinements, Triangulation<dim> &tria)
    {
      Triangulation<dim> half;
      GridGenerator::half_hyper_ball(half, Point<dim>(), radius);
      half.refine_global(refinements);
      GridGenerator::flatten_triangulation(half, tria);
    }

    /** Whether every vertex of @p face has the coordinate @p value in direction @p d. */
    template <typename Face>
    bool
    on_plane(const Face &face, const unsigned int d, const double value, const double tolerance)
    {
      for (const unsigned int v : face->vertex_indices())
        if (std::abs(face->vertex(v)[d] - value) > tolerance)
          return false;
      return true;
    }
  } // namespace


  template <int dim>
  void
  CurvedBody::order_cells(Triangulation<dim> &tria)
  {
    // RT0 needs consistently oriented lines: otherwise the normal flux of a
    // shared face means opposite directions in the two cells, the space is
    // not H(div)-conforming and the embedding matrices of the two parents
    // of a child face disagree. The refined half ball is not consistently
    // oriented, so its cells are reordered (the test tests/unit/
    // level_transfer pins the exact embedding on these meshes).
    auto description = GridTools::get_coarse_mesh_description(tria);
    GridTools::consistently_order_cells(std::get<1>(description));
    tria.clear();
    tria.create_triangulation(std::get<0>(description), std::get<1>(description), SubCellData());
  }


  void
  CurvedBody::half_disc(const Point<2> &   center,
                        const double       radius,
                        const unsigned int refinements,
                        const double       gamma,
                        Triangulation<2> & tria)
  {
    // deal.II's half disc turned by -90 degrees, then graded
    refined_half_ball(radius, refinements, tria);
    GridTools::transform(
      [gamma, radius, center](const Point<2> &p) {
        // p is in the half disc x >= 0 around the origin; the x axis
        // (theta = 0) is turned to point down
        const auto [r, theta] = graded(p.norm(), std::atan2(p[1], p[0]), radius, gamma);
        return Point<2>(center[0] + r * std::sin(theta), center[1] - r * std::cos(theta));
      },
      tria);
    order_cells(tria);
  }


  void
  CurvedBody::half_ball(const Point<3> &   center,
                        const double       radius,
                        const unsigned int refinements,
                        const double       gamma,
                        Triangulation<3> & tria)
  {
    refined_half_ball(radius, refinements, tria);
    GridTools::transform(
      [gamma, radius, center](const Point<3> &p) {
        // p is in the half ball x >= 0 around the origin. The x axis is
        // turned to point down by (x, y, z) -> (z, y, -x), a rotation
        // (determinant 1: the cells keep their orientation). The direction
        // in the horizontal plane is taken from (z, y) itself and not
        // through an angle, so that the points on the planes y = 0 and
        // z = 0 stay exactly on them: the half ball is symmetric about
        // both, and a quarter of it is a quarter model (prm/meshes/).
        const double rho = std::sqrt(p[1] * p[1] + p[2] * p[2]);
        const auto [r, theta] =
          graded(p.norm(), std::atan2(rho, p[0]), radius, gamma);
        const double horizontal = r * std::sin(theta);
        return Point<3>(center[0] + (rho > 0 ? horizontal * p[2] / rho : 0.),
                        center[1] + (rho > 0 ? horizontal * p[1] / rho : 0.),
                        center[2] - r * std::cos(theta));
      },
      tria);
    order_cells(tria);
  }


  void
  CurvedBody::make(const Parameters::Geometry &geometry,
                   const double                length,
                   Triangulation<2> &          tria)
  {
    const Point<2> center(geometry.center[0] / length, geometry.center[1] / length);
    const double   radius = geometry.radius / length;
    half_disc(center, radius, geometry.coarse_refinements, geometry.grading, tria);
    // boundary ids: 0 curved, 1 flat top (by position)
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const bool top = on_plane(face, 1, center[1], 1e-10 * radius);
            face->set_boundary_id(top ? 1 : 0);
            face->set_manifold_id(top ? numbers::flat_manifold_id : 0);
          }
    tria.set_manifold(0, SphericalManifold<2>(center));
  }


  void
  CurvedBody::make(const Parameters::Geometry &geometry,
                   const double                length,
                   Triangulation<3> &          tria)
  {
    Point<3> center;
    for (unsigned int d = 0; d < 3; ++d)
      center[d] = geometry.center[d] / length;
    const double radius    = geometry.radius / length;
    const double tolerance = 1e-10 * radius;
    const bool   ball      = geometry.shape == Parameters::Geometry::Shape::half_ball;
    const double z0 = center[2] - geometry.length / length / 2, z1 = z0 + geometry.length / length;
    if (ball)
      half_ball(center, radius, geometry.coarse_refinements, geometry.grading, tria);
    else
      {
        // the half disc's cross-section, extruded along z
        Triangulation<2> section;
        half_disc(Point<2>(center[0], center[1]),
                  radius,
                  geometry.coarse_refinements,
                  geometry.grading,
                  section);
        std::vector<double> slices;
        for (unsigned int k = 0; k <= geometry.length_subdivisions; ++k)
          slices.push_back(z0 + (z1 - z0) * k / geometry.length_subdivisions);
        Triangulation<3> extruded;
        GridGenerator::extrude_triangulation(section, slices, extruded);
        tria.copy_triangulation(extruded);
        order_cells(tria);
      }
    // boundary ids by position: 1 flat top, 2 and 3 the cylinder's ends,
    // 0 the curved rest, which gets the manifold (its edges too: the rims
    // of the flat faces are curved)
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const types::boundary_id id =
              !ball && on_plane(face, 2, z0, tolerance)   ? 2 :
              !ball && on_plane(face, 2, z1, tolerance)   ? 3 :
              on_plane(face, ball ? 2 : 1, center[ball ? 2 : 1], tolerance) ? 1 :
                                                                              0;
            face->set_boundary_id(id);
            if (id == 0)
              face->set_all_manifold_ids(0);
          }
    if (ball)
      tria.set_manifold(0, SphericalManifold<3>(center));
    else
      tria.set_manifold(0, CylindricalManifold<3>(Tensor<1, 3>({0., 0., 1.}), center));
  }
} // namespace FoslsContact
