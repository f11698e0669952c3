#ifndef fosls_contact_solvers_contact_face_relations_h
#define fosls_contact_solvers_contact_face_relations_h

#include <fosls_contact/discretization/discretization.h>

#include <array>
#include <utility>
#include <vector>

namespace FoslsContact
{
  /**
   * A coarse contact face of level l - 1 owned here and what its coarse
   * obstacles need from level l (paper eqs. 13, 25-30): its sons, and the
   * coarse contact edges of the face (the face itself in 2D) with the fine
   * normal DoFs at their ends and midpoints; in 3D the face's center. All
   * DoFs are local indices: coarse ones of level l - 1, fine ones of
   * level l. The coarse cell of a boundary face is the one cell at it, so
   * every coarse contact face is owned by exactly one process, which has
   * all its children.
   */
  struct FaceRelation
  {
    types::global_dof_index              coarse_dof;
    std::vector<types::global_dof_index> sons;
    /**
     * The fine DoFs of the coarse cell's children that do not lie on one
     * of its other faces (sorted): the DoFs the flux rerouting may use, so
     * that the rerouted column stays inside the coarse cell and the
     * Galerkin operator on the coupling pattern of the coarse cells.
     */
    std::vector<types::global_dof_index> inside;
    /** A coarse contact edge of the face: both ends and the midpoint. */
    struct Edge
    {
      /** coarse normal DoFs of the ends (invalid if an end is not bounded) */
      std::array<types::global_dof_index, 2> coarse;
      /** fine normal DoFs of the ends */
      std::array<types::global_dof_index, 2> fine;
      types::global_dof_index                fine_midpoint;
    };
    std::vector<Edge> edges;
    /** 3D: the fine normal DoF of the face center, or invalid. */
    types::global_dof_index fine_center = numbers::invalid_dof_index;
    /** 3D: the coarse normal DoFs of the face's bounded vertices. */
    std::vector<types::global_dof_index> coarse_vertices;
    /**
     * A tangential row of the face: its coarse RT DoF of stress row m > 0
     * in the face's rotated coordinates (a tangential traction) and the
     * sons' DoFs of that row.
     */
    struct TangentialRow
    {
      types::global_dof_index              coarse_dof;
      std::vector<types::global_dof_index> sons;
    };
    /**
     * With friction in 2D, the face's tangential row, whose truncated
     * sons FluxRerouting::linear_columns() treats; empty otherwise
     * (ContactFaceRelations::tangential_rows(); without friction the
     * tangential tractions are fixed on every level).
     */
    std::vector<TangentialRow> tangential;
  };


  /**
   * How the contact faces of level l - 1 relate to those of level l: the
   * geometry that the coarse obstacles (CoarseObstacles) and the flux
   * rerouting (FluxRerouting) work with, found once from the mesh so that
   * neither of them walks cells. Built once per level by
   * MultilevelHierarchy.
   */
  template <int dim>
  struct ContactFaceRelations
  {
    ContactFaceRelations() = default;
    /**
     * The relations between level @p coarse_index of @p coarse_mesh and
     * level @p fine_index of @p fine_mesh: two consecutive levels of one
     * discretization, or of the levels of an adaptive mesh (LevelMeshes),
     * whose cells are matched by their CellId. A coarse contact face whose
     * cell the fine level does not refine is its own son, and each of its
     * vertices its own coarse obstacle.
     */
    ContactFaceRelations(const Discretization<dim> &coarse_mesh,
                         const unsigned int         coarse_index,
                         const Discretization<dim> &fine_mesh,
                         const unsigned int         fine_index);

    /**
     * Whether the faces carry their tangential rows (FaceRelation::
     * tangential): with friction in 2D. In 3D the rerouted tangential
     * columns took more Newton steps where the traction pairs turn on
     * their circles: the 3D Cattaneo-Mindlin scene on its graded mesh
     * (`prm/cattaneo_mindlin_3d_fine.prm`) at most 7 per Tresca problem
     * instead of 4, and 1,488 s instead of 937 s, the full-slip cube of
     * `tests/solver/friction_3d` 35 instead of 30 (`bench/friction.py`).
     */
    static bool tangential_rows(const Scene<dim> &scene)
    {
      return dim == 2 && scene.has_friction();
    }

    /** Coarse contact faces of level l - 1 owned here. */
    std::vector<FaceRelation> faces;
    /**
     * The entries (local fine DoF, local coarse contact face DoF) the flux
     * rerouting may give the prolongation (MultilevelHierarchy::
     * rerouting_entries()): for the normal row of each face, and for its
     * tangential rows where the faces carry them (tangential_rows()).
     */
    std::vector<std::pair<types::global_dof_index, types::global_dof_index>> rerouting;

  private:
    /**
     * The FaceRelation of contact face @p f of the coarse @p cell, which is
     * @p fine_cell on the fine level's mesh (the same cell, or the parent
     * of its fine cells); its tangential rows if @p tangential.
     */
    template <typename Iterator, typename FineIterator>
    FaceRelation face_relation(const Iterator &      cell,
                               const FineIterator &  fine_cell,
                               const unsigned int    f,
                               const LevelData<dim> &coarse,
                               const LevelData<dim> &fine,
                               const bool            tangential) const;
  };
} // namespace FoslsContact

#endif
