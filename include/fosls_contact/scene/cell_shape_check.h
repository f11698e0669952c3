#ifndef fosls_contact_scene_cell_shape_check_h
#define fosls_contact_scene_cell_shape_check_h

#include <deal.II/grid/tria.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/scene/mesh_file.h>

namespace FoslsContact
{
  /**
   * The check that no cell of a mesh is inverted, on any level. Refinement
   * moves boundary vertices onto curved boundaries, so a coarse mesh whose
   * cells are all fine can have inverted cells on finer levels, where the
   * FOSLS functional is no longer a sum of squares; the message names the
   * parameter that caused it, which depends on the kind of geometry.
   */
  template <int dim>
  struct CellShapeCheck
  {
    /**
     * Coarse cells of this aspect ratio and more are refused: the entries
     * of div sigma scale with the inverse of a cell's thickness, the other
     * terms' with its edges, and double precision loses the functional in
     * between: at this ratio the round-off of J exceeds J, the multigrid
     * no longer converges and the solvers' forces part (doc/method.md,
     * "Conditioning", measured by tests/solver/round_off_limited).
     */
    static constexpr double aspect_limit = 1e4;

    /**
     * A cell's aspect ratio: its longest edge over its thickness, the
     * measure over the longest edge's power dim - 1 (the side ratio of a
     * rectangle, a^2 / (b c) for a box a >= b, c).
     */
    static double aspect_ratio(const typename Triangulation<dim>::cell_iterator &cell);

    /**
     * Refuse a mesh with a coarse cell of aspect ratio aspect_limit or more,
     * or with a cell whose corner has a Jacobian determinant
     * <= 0 on any level of @p tria (dimensionless, in units of @p length),
     * a mesh of @p geometry (and of @p mesh_file, for Shape = file).
     * Collective on @p comm.
     */
    static void check(const Triangulation<dim> &  tria,
                      const MPI_Comm              comm,
                      const Parameters::Geometry &geometry,
                      const MeshFile<dim> *       mesh_file,
                      const double                length);

  private:
    /** The part of check() for the aspect ratios of the coarse cells. */
    static void check_aspect_ratios(const Triangulation<dim> &  tria,
                                    const Parameters::Geometry &geometry,
                                    const MeshFile<dim> *       mesh_file,
                                    const double                length);
  };
} // namespace FoslsContact

#endif
