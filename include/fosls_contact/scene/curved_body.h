#ifndef fosls_contact_scene_curved_body_h
#define fosls_contact_scene_curved_body_h

#include <deal.II/grid/tria.h>

#include <fosls_contact/parameters/parameters.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The built-in curved bodies of Geometry/Shape, each the lower half of a
   * round body with its flat face on top, for Hertz contact on a plane
   * below it without a mesh file:
   *  - half disc (2D): boundary ids 0 = curved side, 1 = flat top;
   *  - half ball (3D): 0 = curved surface, 1 = flat top;
   *  - half cylinder (3D, axis along z): 0 = curved side, 1 = flat top,
   *    2 and 3 = the end faces at the smaller and the larger z.
   *
   * Each is made of deal.II's half ball (in 2D the half disc), refined
   * Coarse refinements times and flattened into a coarse mesh, turned so
   * that its flat face is on top, and optionally graded toward the lowest
   * point (line): in polar coordinates around the center, the angle from
   * the downward direction and the distance to the curved boundary are
   * raised to the power Grading, which keeps the curved boundary and the
   * flat top in place and puts small cells where the contact starts. The
   * half cylinder is the half disc extruded along z (Length subdivisions
   * cells). The curved boundary gets a SphericalManifold (a
   * CylindricalManifold), so that refinement follows it.
   *
   * The cells are ordered consistently (GridTools::consistently_order_cells)
   * after the grading: RT0 needs it for the level transfer (the refined
   * half ball is not, doc/method.md section 2).
   */
  class CurvedBody
  {
  public:
    /** The half disc of @p geometry divided by @p length. */
    static void make(const Parameters::Geometry &geometry,
                     const double                length,
                     Triangulation<2> &          tria);
    /** The half ball or half cylinder of @p geometry divided by @p length. */
    static void make(const Parameters::Geometry &geometry,
                     const double                length,
                     Triangulation<3> &          tria);

  private:
    /** The graded half disc of @p radius around @p center, ordered, without ids. */
    static void half_disc(const Point<2> &   center,
                          const double       radius,
                          const unsigned int refinements,
                          const double       grading,
                          Triangulation<2> & tria);
    /** The graded half ball, ordered, without ids. */
    static void half_ball(const Point<3> &   center,
                          const double       radius,
                          const unsigned int refinements,
                          const double       grading,
                          Triangulation<3> & tria);

    /** Rebuild @p tria from its coarse cells, ordered consistently. */
    template <int dim>
    static void order_cells(Triangulation<dim> &tria);
  };
} // namespace FoslsContact

#endif
