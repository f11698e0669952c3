#ifndef fosls_contact_discretization_discretization_h
#define fosls_contact_discretization_discretization_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/qp/matrix_entry_import.h>
#include <fosls_contact/scene/scene.h>

#include <array>
#include <map>
#include <set>

namespace FoslsContact
{
  /**
   * The role of one degree of freedom in the constrained quadratic problem.
   */
  enum class DoFRole : unsigned char
  {
    free,    ///< unconstrained
    fixed,   ///< Dirichlet u, Neumann sigma n, tangential contact traction
    bounded, ///< contact: normal displacement <= g or normal stress <= 0
  };

  /**
   * A block of DoFs whose coordinates are changed to the normal-tangential
   * system of paper section 4.3: x_cartesian = matrix * x_rotated on
   * `dofs` (local indices). The first rotated coordinate is the normal one.
   */
  template <int dim>
  struct RotationBlock
  {
    std::array<types::global_dof_index, dim> dofs;
    FullMatrix<double>                       matrix;
    FullMatrix<double>                       inverse;
  };

  /**
   * A contact vertex on one level: u.n <= g bounds DoF `normal_dof` (a
   * local index; `owned` if this process owns it).
   */
  template <int dim>
  struct ContactVertex
  {
    unsigned int             vertex_index;
    types::global_dof_index  normal_dof;
    Point<dim>               point;
    Tensor<1, dim>           normal;
    double                   gap;
    bool                     owned;
  };

  /** A contact face on one level: (sigma n).n <= 0 bounds `normal_dof`. */
  template <int dim>
  struct ContactFace
  {
    unsigned int             face_index;
    types::global_dof_index  normal_dof;
    Point<dim>               center;
    Tensor<1, dim>           normal;
    double                   area;
    bool                     owned;
  };

  /**
   * Everything the algebra needs to know about one level, on this process:
   * the DoFs it owns and its ghost DoFs (those of the ghost cells around
   * its own cells; `partitioner`), and for all of them, in local indices
   * (LevelVector): the DoF roles, the values of fixed DoFs and the upper
   * bounds (both in the rotated basis), the rotations, and the contact
   * entities.
   */
  template <int dim>
  struct LevelData
  {
    /** The number of DoFs of the level (all processes). */
    types::global_dof_index                 n_dofs = 0;
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
    /** Local DoFs: owned, then ghosts. */
    unsigned int n_owned() const { return partitioner->locally_owned_size(); }
    unsigned int n_local() const
    {
      return partitioner->locally_owned_size() + partitioner->n_ghost_indices();
    }
    /** The global index of local DoF @p i. */
    types::global_dof_index global(const unsigned int i) const
    {
      return partitioner->local_to_global(i);
    }
    std::vector<DoFRole>                    role;
    LevelVector                             fixed_values;
    LevelVector                             upper_bounds;
    std::vector<RotationBlock<dim>>         rotations;
    /** For each local DoF, the index of its rotation block, or invalid. */
    std::vector<unsigned int>               rotation_of_dof;
    /** The contact vertices and faces of the cells of this process. */
    std::vector<ContactVertex<dim>>         contact_vertices;
    std::vector<ContactFace<dim>>           contact_faces;
    /**
     * vertex index -> its displacement DoFs (component by component), for
     * the vertices of the cells here; local indices.
     */
    std::map<unsigned int, std::array<types::global_dof_index, dim>> vertex_dofs;
    /** face index -> its RT DoFs (stress row by row); local indices. */
    std::map<unsigned int, std::array<types::global_dof_index, dim>> face_dofs;
    /**
     * The vertices of the cells this process owns on the level: it relaxes
     * the patches there that have a DoF it owns, and all cells at them are
     * here.
     */
    std::set<unsigned int> owned_cell_vertices;
    /**
     * The coupling pattern of the level's cells, in local indices, for the
     * rows this process holds: its own DoFs, and the ghost DoFs of the
     * vertex patches at the vertices of its cells (the patch smoother
     * relaxes every patch with a DoF of its own, and needs the rows of all
     * the patch's DoFs). Every level matrix lies on it: the assembled one
     * and the Galerkin operators (MonotoneMultigrid).
     */
    SparsityPattern                         sparsity;
    /** The ghost rows of `sparsity`, copied from their owners. */
    MatrixEntryImport                       ghost_rows;
  };

  /**
   * Call @p f(dof) for the DoFs of the Arnold-Falk-Winther patch of vertex
   * @p v of @p cell that lie in this cell: the vertex's displacement DoFs
   * and the RT DoFs (all stress rows) of the cell's faces at the vertex.
   * The patch is the union over the cells at the vertex.
   */
  template <int dim, typename Iterator, typename Function>
  void
  for_patch_dofs_in_cell(const LevelData<dim> &level,
                         const Iterator &      cell,
                         const unsigned int    v,
                         const Function &      f)
  {
    for (const auto dof : level.vertex_dofs.at(cell->vertex_index(v)))
      f(dof);
    for (const unsigned int face : cell->face_indices())
      for (unsigned int i = 0; i < GeometryInfo<dim>::vertices_per_face; ++i)
        if (GeometryInfo<dim>::face_to_cell_vertices(face, i) == v)
          for (const auto dof : level.face_dofs.at(cell->face(face)->index()))
            f(dof);
  }


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
   * The mesh is a parallel::distributed::Triangulation (p4est) with
   * multigrid levels, distributed over the processes of @p comm; with one
   * process it is the whole mesh. On every level a process owns the cells
   * p4est gives it (a coarse cell belongs to the owner of its first child)
   * and sees the ghost cells around them; measured (2D and 3D, 1 to 3
   * processes): the cells around every vertex of an owned cell, the
   * children of owned cells and the parents of ghost cells are always
   * there. That is what the level data, the patches and the transfer
   * below rely on.
   */
  template <int dim>
  class Discretization
  {
  public:
    Discretization(const Scene<dim> &scene,
                   const unsigned int n_levels,
                   const MPI_Comm     comm);

    const parallel::distributed::Triangulation<dim> &get_triangulation() const
    {
      return triangulation;
    }
    MPI_Comm get_communicator() const { return triangulation.get_communicator(); }
    /** Whether @p cell (of any level) has DoFs here: owned or ghost. */
    template <typename Iterator>
    static bool is_present(const Iterator &cell)
    {
      return cell->level_subdomain_id() != numbers::artificial_subdomain_id;
    }
    const DoFHandler<dim> &   get_dof_handler() const { return dof_handler; }
    const FESystem<dim> &     get_fe() const { return fe; }
    const Mapping<dim> &      get_mapping() const { return mapping; }
    const Scene<dim> &        get_scene() const { return scene; }

    unsigned int n_levels() const { return triangulation.n_global_levels(); }
    unsigned int finest_level() const { return n_levels() - 1; }
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

    /** The Householder reflection H with H e_1 = n (paper section 4.3). */
    static FullMatrix<double> householder(const Tensor<1, dim> &n);

    /**
     * The rotation R (x_cart = R x_rot) of a contact vertex with obstacle
     * normal @p n: R e_1 = n, and e_k (up to sign) is a column for every k
     * with n_k = 0, so a roller's prescribed components stay single
     * rotated coordinates. H(n) when n_1 != 0; when n_1 = 0 an orthogonal
     * matrix that equals H(n) for n = +-e_j. A function of n alone: every
     * process that holds the vertex builds the same.
     */
    static FullMatrix<double> vertex_rotation(const Tensor<1, dim> &n);

  private:
    /**
     * The owned DoFs of level @p l sorted by their keys: the position of
     * the support point (the vertex, the face center; x first), the base
     * element and the component (dim + 2 numbers), followed by the DoF's
     * global index. The keys are geometry only, so the same on any number
     * of processes.
     */
    std::vector<std::array<double, dim + 3>> owned_dof_keys(const unsigned int l) const;
    /**
     * Renumber the DoFs of level @p l, within each process's owned range,
     * in the order of owned_dof_keys(). The patch smoother sweeps the
     * vertices of one kind in that order (MultilevelHierarchy:
     * VertexKey), so the values a patch gathers and those of the next
     * patches lie next to each other in memory; p4est numbers them in the
     * cells' Z-order, which puts a vertex's neighbours above and below it
     * far apart. With one process this numbering is the order of the keys
     * over the whole level; with several, each process's range is, so the
     * numbering depends on the partition (see sweep_order()).
     */
    void renumber_level(const unsigned int l);
    void setup_level(const unsigned int l);
    /** x <- R x (or R^{-1} x) block by block on level @p l. */
    void apply_rotations(const unsigned int l,
                         LevelVector &      x,
                         const bool         inverse) const;

    const Scene<dim> &      scene;
    parallel::distributed::Triangulation<dim> triangulation;
    std::shared_ptr<const Utilities::MPI::Partitioner> active_partitioner;
    FESystem<dim>           fe;
    MappingQ<dim>           mapping;
    DoFHandler<dim>         dof_handler;
    std::vector<LevelData<dim>> levels;
    double                  coarse_ratio = 1;
  };
} // namespace FoslsContact

#endif
