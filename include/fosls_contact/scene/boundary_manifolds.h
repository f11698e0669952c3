#ifndef fosls_contact_scene_boundary_manifolds_h
#define fosls_contact_scene_boundary_manifolds_h

#include <deal.II/grid/tria.h>

#include <fosls_contact/parameters/parameters.h>

#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The curved surfaces of a file mesh's boundary (Geometry/Manifolds): a
   * sphere (a circle in 2D) or a cylinder per boundary id.
   *
   * A mesh file holds only vertices: refined, its boundary faces would stay
   * flat facets and the finer levels would not get closer to the curved
   * surface (a sphere of 6 coarse facets stays a polyhedron). With a
   * manifold the new vertices of these faces lie on the surface, as they do
   * for the built-in curved bodies. The faces of the id and, in 3D, their
   * edges get the manifold (manifold id = boundary id), so an edge where a
   * curved face meets a flat one (the rim of a flat top) follows the curve.
   * The cells keep straight interior faces: the new vertex in a cell is the
   * mean of the surrounding ones, which is what deal.II's own generators
   * (hyper_ball, half_hyper_ball) do with their boundaries.
   */
  template <int dim>
  class BoundaryManifolds
  {
  public:
    /**
     * The surfaces of @p manifolds (in the scene's units), for a mesh
     * divided by the reference length @p length.
     */
    BoundaryManifolds(const std::vector<Parameters::Geometry::Manifold> &manifolds,
                      const double                                       length);

    /**
     * Attach the surfaces to the dimensionless @p tria. Every named id must
     * be a boundary id of the mesh and every vertex of its faces must lie on
     * its surface (to 1e-3 of the radius); @p mesh names the mesh in the
     * errors.
     */
    void attach(Triangulation<dim> &tria, const std::string &mesh) const;

  private:
    /** The distance of the dimensionless @p p from the surface of @p m, relative to its radius. */
    double distance(const Parameters::Geometry::Manifold &m, const Point<dim> &p) const;

    const std::vector<Parameters::Geometry::Manifold> manifolds;
    const double                                      length;
  };
} // namespace FoslsContact

#endif
