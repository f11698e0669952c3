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
     * Refuse a mesh with a cell whose corner has a Jacobian determinant
     * <= 0 on any level of @p tria (dimensionless, in units of @p length),
     * a mesh of @p geometry (and of @p mesh_file, for Shape = file).
     * Collective on @p comm.
     */
    static void check(const Triangulation<dim> &  tria,
                      const MPI_Comm              comm,
                      const Parameters::Geometry &geometry,
                      const MeshFile<dim> *       mesh_file,
                      const double                length);
  };
} // namespace FoslsContact

#endif
