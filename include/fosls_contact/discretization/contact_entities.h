#ifndef fosls_contact_discretization_contact_entities_h
#define fosls_contact_discretization_contact_entities_h

#include <deal.II/distributed/tria.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/discretization/boundary_face_conditions.h>
#include <fosls_contact/discretization/level_data.h>
#include <fosls_contact/scene/scene.h>

#include <array>
#include <string>

namespace FoslsContact
{
  /**
   * The contact vertices and faces of one level and their normal-tangential
   * rotations (paper section 4.3): which vertex DoF is bounded by the gap,
   * how a vertex of both a roller and the contact boundary keeps its
   * prescribed components as single rotated coordinates, and which data
   * cannot be held (a prescribed displacement into the obstacle). The
   * contact constraints become box constraints only through this
   * bookkeeping, so it is in one place.
   */
  template <int dim>
  class ContactEntities
  {
  public:
    using BoundaryData = typename BoundaryFaceConditions<dim>::BoundaryData;

    ContactEntities(const Scene<dim> &scene, const Triangulation<dim> &triangulation);

    /**
     * The contact vertices of level @p l (@p data): the vertices of the contact
     * faces that no Dirichlet face prescribes u.n at. Refuses a
     * prescribed displacement into the obstacle and a roller whose
     * prescribed components the normal has a part along.
     */
    void set_contact_vertices(LevelData<dim> &data, const BoundaryData &boundary) const;
    /**
     * The rotation blocks and contact entities of the level @p data, once
     * the roles of its ghost DoFs are those of their owners.
     */
    void add_rotations(LevelData<dim> &data, const BoundaryData &boundary) const;
    /**
     * With friction: the contact faces of @p data with their slip DoFs
     * (LevelData::friction_faces), after add_rotations().
     */
    void add_friction_faces(LevelData<dim> &data, const BoundaryData &boundary) const;

  private:
    /**
     * A contact vertex on a roller (Dirichlet in the components @p mask
     * with the values @p values): the rotated coordinates that are the
     * prescribed components are fixed, u.n is bounded by @p gap. False
     * (nothing set) if @p n has a part along a prescribed component.
     */
    bool roller_contact_vertex(LevelData<dim> &                                data,
                               const std::array<types::global_dof_index, dim> &dofs,
                               const std::array<bool, dim> &                   mask,
                               const Tensor<1, dim> &                          n,
                               const double                                    gap,
                               const Vector<double> &                          values) const;
    /**
     * The penetration error of set_contact_vertices(), over all processes:
     * the largest penetration of a prescribed vertex (@p penetration, this
     * process's). Collective.
     */
    void check_penetration(const LevelData<dim> &data, double penetration) const;
    /**
     * A displacement prescribed at a contact vertex exceeds the gap when
     * u.n - g is above this times 1 + |u.n| + |g|: round-off of the data
     * (sin(pi) = 1.2e-16 against a gap of 0) passes.
     */
    static constexpr double penetration_round_off = 1e-12;

    const Scene<dim> &        scene;
    const Triangulation<dim> &triangulation;
  };
} // namespace FoslsContact

#endif
