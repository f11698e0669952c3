#ifndef fosls_contact_discretization_boundary_face_conditions_h
#define fosls_contact_discretization_boundary_face_conditions_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <fosls_contact/discretization/level_data.h>
#include <fosls_contact/scene/scene.h>

#include <array>
#include <map>
#include <vector>

namespace FoslsContact
{
  /**
   * The boundary conditions of the scene as roles, values and bounds of the
   * level DoFs on the boundary faces. In FOSLS the traction is a value of
   * the stress unknown, so Neumann data are essential conditions like the
   * Dirichlet ones; this class turns each kind of boundary face into the
   * DoF roles the constrained QP works with, and collects what the contact
   * vertices and rotations (ContactEntities) need from the same faces.
   */
  template <int dim>
  class BoundaryFaceConditions
  {
  public:
    /**
     * The boundary conditions of one level as apply()
     * collects them from the boundary faces here, for the contact vertices
     * and the rotations.
     */
    struct BoundaryData
    {
      /**
       * Dirichlet vertices with the components prescribed there (the
       * union over their Dirichlet faces: a corner of a clamped and a
       * roller side is clamped).
       */
      std::map<unsigned int, std::array<bool, dim>> dirichlet_vertices;
      /** The vertices of the contact faces, with their positions. */
      std::map<unsigned int, Point<dim>> contact_vertex_points;
      /** A contact face, for its rotation (ContactEntities::add_rotations()). */
      struct ContactFaceData
      {
        unsigned int                             face_index;
        std::array<types::global_dof_index, dim> dofs;
        Point<dim>                               center;
        Tensor<1, dim>                           normal;
        /** The face's area and the mean normal component of its RT basis function. */
        double area, c;
        /** Its vertices (indices of the triangulation). */
        std::array<unsigned int, GeometryInfo<dim>::vertices_per_face> vertices;
      };
      std::vector<ContactFaceData> contact_faces;
    };

    BoundaryFaceConditions(const Scene<dim> &scene,
                           const Mapping<dim> &mapping,
                           const DoFHandler<dim> &dof_handler);

    /**
     * The roles and values of the DoFs on the Dirichlet, Neumann and
     * contact faces of level @p l: prescribed displacements, tractions as
     * the L2 projection onto the face's normal-flux basis function (they
     * are essential here), the contact faces' normal stress bounded.
     */
    BoundaryData apply(const unsigned int l, LevelData<dim> &data) const;

  private:
    /**
     * Refuse an obstacle normal at the contact boundary's point @p p
     * (dimensionless) that does not point out of the body, whose outward
     * normal there is @p outward.
     */
    void check_obstacle_normal(const Point<dim> &p, const Tensor<1, dim> &outward) const;

    /**
     * A contact face: the normal traction <= 0, the tangential ones 0, or
     * with @p friction bounded by the slip bound (DoFRole::traction).
     */
    static void bound_contact_face(LevelData<dim> &                                data,
                                   const std::array<types::global_dof_index, dim> &face_rt,
                                   const bool                                      friction);

    const Scene<dim> &     scene;
    const Mapping<dim> &   mapping;
    const DoFHandler<dim> &dof_handler;
  };
} // namespace FoslsContact

#endif
