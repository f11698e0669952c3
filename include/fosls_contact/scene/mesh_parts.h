#ifndef fosls_contact_scene_mesh_parts_h
#define fosls_contact_scene_mesh_parts_h

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <string>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The check that every part of a mesh is held against rigid motion by a
   * Dirichlet boundary of its own.
   *
   * A mesh file can hold bodies that are not connected through faces: two
   * blocks side by side, or a cell that touches the rest at a vertex or an
   * edge only (its faces are all boundary faces). The functional does not
   * couple them, so a part without a Dirichlet boundary moves freely: its
   * rigid motions make the matrix singular. The check of the rigid motions
   * (ProblemChecks) tests the motions of the whole mesh, which another
   * part holds, and the definiteness check then finds the contact Schur
   * complement indefinite and blames the complementarity weight; the cause
   * is named here instead, with a point of the part. The obstacle does not
   * hold a part either: it bounds the normal displacement from one side
   * only, and frictionless contact leaves the tangential motions free.
   *
   * A mesh of one part is left to the check of the rigid motions, which
   * also names the motion that is free.
   */
  template <int dim>
  struct MeshParts
  {
    /**
     * Refuse a coarse mesh @p tria (dimensionless, in units of @p length)
     * with more than one part (cells connected through faces) of which one
     * has no Dirichlet face (@p is_dirichlet of its boundary id); @p
     * is_contact tells which ids are contact boundaries, for the message.
     * @p mesh names the mesh ("the mesh file 'x.msh'").
     */
    static void check(const Triangulation<dim> &                          tria,
                      const std::function<bool(const types::boundary_id)> &is_dirichlet,
                      const std::function<bool(const types::boundary_id)> &is_contact,
                      const double                                         length,
                      const std::string &                                  mesh);
  };
} // namespace FoslsContact

#endif
