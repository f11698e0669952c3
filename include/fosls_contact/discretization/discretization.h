#ifndef fosls_contact_discretization_discretization_h
#define fosls_contact_discretization_discretization_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/discretization/level_data.h>
#include <fosls_contact/parameters/adaptivity.h>
#include <fosls_contact/qp/matrix_list_memory.h>
#include <fosls_contact/scene/scene.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * The discretization of paper section 4.1: the FESystem
   * Q1^d x RT0^d (row m of sigma is the m-th RT0 field) on a hierarchy of
   * uniformly refined meshes, with level DoFs on every level.
   *
   * All algebra in this program lives in the *level* numbering, the finest
   * level included: on a uniformly refined mesh the finest level is the
   * active mesh, and using one numbering for every level makes the
   * multilevel hierarchy, the constraints and the assembly one code path.
   * Output maps the finest level back to the active numbering.
   *
   * An adaptively refined mesh (refine(), Adaptivity) adds its active mesh
   * as the finest level, in the active numbering, with its hanging nodes
   * eliminated (LevelData::hanging); the uniform levels below it stay.
   *
   * How the mesh is held (MeshDistribution):
   * - partitioned: a parallel::distributed::Triangulation (p4est) with
   *   multigrid levels, distributed over the processes of @p comm. On
   *   every level a process owns the cells p4est gives it (a coarse cell
   *   belongs to the owner of its first child) and sees the ghost cells
   *   around them; as tested (2D and 3D, 1 to 3 processes), the cells
   *   around every vertex of an owned cell, the children of owned cells
   *   and the parents of ghost cells are always there. That is what the
   *   level data, the patches and the transfer below rely on.
   * - replicated: every process holds the whole mesh
   *   (ReplicatedTriangulation), and the cells (and so the DoFs) are
   *   divided among the processes in Z-order. Adaptive
   *   refinement needs it. A hanging DoF's masters lie on the coarse
   *   neighbour of its refined face; for a DoF of a ghost cell that
   *   neighbour need not touch an owned cell, and p4est's ghost layer does
   *   not hold it. With the whole mesh everywhere every master is here,
   *   and so are the cells that the coarsened meshes of the multilevel
   *   solver (LevelMeshes) are built from. Every DoF is then a ghost of
   *   every process: the work is divided, the vectors are not. deal.II
   *   9.4 does not renumber the levels of such a mesh, so they keep its
   *   numbering (LevelDoFNumbering is skipped), which changes with the
   *   partition after every refinement.
   * With one process both hold the whole mesh; their level numberings
   * differ, and with them the round-off.
   */
  template <int dim>
  class Discretization
  {
  public:
    /** How the processes hold the mesh (see the class documentation). */
    enum class MeshDistribution
    {
      partitioned,
      replicated
    };

    Discretization(const Scene<dim> &     scene,
                   const unsigned int     n_levels,
                   const MPI_Comm         comm,
                   const MeshDistribution distribution = MeshDistribution::partitioned);

    const parallel::TriangulationBase<dim> &get_triangulation() const { return *triangulation; }
    MPI_Comm get_communicator() const { return triangulation->get_communicator(); }
    MeshDistribution get_mesh_distribution() const { return distribution; }
    /** Whether @p cell (of any level) has DoFs here: owned or ghost. */
    template <typename Iterator>
    static bool is_present(const Iterator &cell)
    {
      return level_cell_is_present(cell);
    }
    const DoFHandler<dim> &   get_dof_handler() const { return dof_handler; }
    const FESystem<dim> &     get_fe() const { return fe; }
    const Mapping<dim> &      get_mapping() const { return mapping; }
    const Scene<dim> &        get_scene() const { return scene; }

    /**
     * The levels of the algebra: the uniformly refined mesh levels and, once
     * the mesh is refined adaptively (refine()), the active mesh as one
     * more level on top of them.
     */
    unsigned int n_levels() const { return levels.size(); }
    unsigned int finest_level() const { return n_levels() - 1; }
    /**
     * The uniformly refined levels (Geometry/Levels); the multilevel
     * transfer and solvers work on these.
     */
    unsigned int n_uniform_levels() const { return n_uniform; }
    /** Whether the finest level is an adaptively refined active mesh. */
    bool adaptive() const { return levels.back().active_mesh; }

    /**
     * Refine the cells marked by @p criteria (one entry per active cell,
     * the owned ones set: eta_T^2) as @p adaptivity says, with hanging
     * nodes, and set the levels up again: the uniform ones, and the active
     * mesh as the finest. Returns false, refining nothing, if the refined
     * mesh could have more than Adaptivity/Max DoFs DoFs (bounded by the
     * vertices and faces the marked cells add). Each of @p carried is a
     * function on the active mesh (Cartesian, in the active numbering;
     * its ghost values are updated here) and is replaced by its interpolant on the
     * refined mesh (nested spaces: the same function). Needs a replicated
     * mesh (MeshDistribution). Collective.
     */
    bool refine(const Vector<float> &              criteria,
                const Parameters::Adaptivity &     adaptivity,
                const std::vector<LevelVector *> &carried = {});
    /**
     * Refine this uniformly refined mesh into the mesh @p target, a mesh
     * on the same coarse mesh that refines the uniform levels (one of the
     * coarsened meshes that are the levels of the multilevel solver on an
     * adaptively refined mesh, LevelMeshes), and set the levels up again
     * (the active mesh as the finest). The cells are found by their CellId
     * and refined one mesh level at a time; after round k the mesh is
     * @p target with its cells capped at level k + 1, which is balanced as
     * @p target is (capping the levels never increases the level
     * difference of two cells at a vertex), so the mesh's smoothing adds
     * no cell (checked). Replicated mesh only (MeshDistribution).
     * Collective.
     */
    void refine_as(const Triangulation<dim> &target);

    /**
     * Set every level's data up again from the scene's data functions as
     * they are now (a load step, Scene::set_load_step()): the fixed
     * values, bounds and rotations of the boundary. The mesh and the DoF
     * numbering stay, so that a vector of the finest level keeps its
     * meaning; the rotations may change with the obstacle normal, so a
     * vector in the rotated basis is rotated back before and anew after.
     */
    void update_data();

    const LevelData<dim> &level(const unsigned int l) const { return levels[l]; }

    /** h_max / h_min of the coarse mesh. */
    double coarse_mesh_ratio() const { return coarse_ratio; }

    /**
     * Map a vector in the level numbering of the finest level to the
     * active numbering (for DataOut and error integration); the result has
     * its ghost values (those of the active ghost cells).
     */
    LevelVector to_active(const LevelVector &level_vector) const;

    /** x_cartesian = R x_rotated on level @p l (all local entries). */
    void rotate_to_cartesian(const unsigned int l, LevelVector &x) const;
    /** x_rotated = R^{-1} x_cartesian on level @p l (all local entries). */
    void rotate_to_normal_tangential(const unsigned int l, LevelVector &x) const;

    /**
     * The DoFs of level @p l in the order of their support points, base
     * element and component over all processes (the numbering of one
     * process): on process 0 their global indices in that order, empty
     * elsewhere. A method that sweeps in this order does the same on any
     * number of processes (ProjectedGaussSeidel). Collective.
     */
    std::vector<types::global_dof_index> sweep_order(const unsigned int l) const;

    /** The bytes of the mesh (with p4est's forest, where it has one) and the DoF handler. */
    std::size_t mesh_memory_consumption() const;
    /**
     * The bytes of the level data by level: the coupling patterns, the
     * tables of the DoFs at vertices and faces, roles, fixed values,
     * bounds and rotations.
     */
    LevelBytes level_memory_consumption() const;

    /**
     * Free the DoF coupling pattern of level @p l (LevelData::sparsity).
     * It is needed to assemble the level and by the solvers that factorize
     * its matrix (the active set method and the definiteness check order
     * their factorization by it); the multigrid method works on the
     * assembled matrix's own pattern of nonzeros. On the finest level it
     * is the largest part of the level data (a 3D vertex couples with 27
     * vertices and 36 faces, 4 bytes per column), which the multigrid
     * solve then does not hold. Setting the levels up again (refine())
     * builds it again.
     */
    void release_coupling_pattern(const unsigned int l);

  private:
    /**
     * The level data of level @p l: map_level_dofs(), then the roles,
     * fixed values and bounds of the boundary faces
     * (BoundaryFaceConditions) and the contact vertices, the rotations
     * (ContactEntities) and the coupling pattern.
     */
    void setup_level(const unsigned int l);
    /** Distribute the DoFs, renumber the levels and set all levels up. */
    void setup_dofs_and_levels();
    /**
     * The partitioner of level @p l, the arrays of its local DoFs (every
     * DoF free and unbounded) and the DoFs of every vertex and face.
     */
    void map_level_dofs(const unsigned int l);
    /**
     * The coupling pattern of level @p l for the rows held here, and the
     * import of its ghost rows.
     */
    void set_coupling_pattern(const unsigned int l);

    /** x <- R x (or R^{-1} x) block by block on level @p l. */
    void apply_rotations(const unsigned int l,
                         LevelVector &      x,
                         const bool         inverse) const;

    const Scene<dim> &                                scene;
    const MeshDistribution                            distribution;
    std::unique_ptr<parallel::TriangulationBase<dim>> triangulation;
    std::shared_ptr<const Utilities::MPI::Partitioner> active_partitioner;
    FESystem<dim>           fe;
    MappingQ<dim>           mapping;
    DoFHandler<dim>         dof_handler;
    std::vector<LevelData<dim>> levels;
    double                  coarse_ratio = 1;
    unsigned int            n_uniform    = 0;
    /** The active mesh's hanging-node constraints (global indices). */
    AffineConstraints<double> hanging_constraints;
  };
} // namespace FoslsContact

#endif
