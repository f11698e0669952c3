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
#include <deal.II/lac/vector.h>

#include <fosls_contact/qp/algebraic_level.h>
#include <fosls_contact/scene/scene.h>

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace FoslsContact
{
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
   * One level of the discretization on this process: the algebra's view
   * of it (AlgebraicLevel: the DoFs it owns and its ghost DoFs, those of
   * the ghost cells around its own cells, their roles, fixed values and
   * upper bounds in the rotated basis, the coupling pattern), and the
   * mesh's: the rotations, the contact entities, and which DoFs belong to
   * which vertex and face. All DoFs are local indices (LevelVector).
   */
  template <int dim>
  struct LevelData : AlgebraicLevel
  {
    LevelData() { dimension = dim; }

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

    /**
     * The boundary conditions of one level as apply_boundary_faces()
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
      /** A contact face, for its rotation (add_rotations()). */
      struct ContactFaceData
      {
        unsigned int                             face_index;
        std::array<types::global_dof_index, dim> dofs;
        Point<dim>                               center;
        Tensor<1, dim>                           normal;
        /** The face's area and the mean normal component of its RT basis function. */
        double area, c;
      };
      std::vector<ContactFaceData> contact_faces;
    };

    /**
     * The level data of level @p l: map_level_dofs(), then the roles,
     * fixed values and bounds of the boundary faces and the contact
     * vertices, the rotations and the coupling pattern.
     */
    void setup_level(const unsigned int l);
    /** The local level DoFs of @p cell of level @p l. */
    template <typename Iterator>
    void get_local_dofs(const unsigned int                    l,
                        const Iterator &                      cell,
                        std::vector<types::global_dof_index> &dofs) const;
    /**
     * The partitioner of level @p l, the arrays of its local DoFs (every
     * DoF free and unbounded) and the DoFs of every vertex and face.
     */
    void map_level_dofs(const unsigned int l);
    /**
     * The roles and values of the DoFs on the Dirichlet, Neumann and
     * contact faces of level @p l: prescribed displacements, tractions as
     * the L2 projection onto the face's normal-flux basis function (they
     * are essential here), the contact faces' normal stress bounded.
     */
    BoundaryData apply_boundary_faces(const unsigned int l);
    /** A contact face: tangential tractions 0, the normal one <= 0. */
    static void bound_contact_face(LevelData<dim> &                                data,
                                   const std::array<types::global_dof_index, dim> &face_rt);
    /**
     * The contact vertices of level @p l: the vertices of the contact
     * faces that no Dirichlet face prescribes u.n at. Refuses a
     * prescribed displacement into the obstacle and a roller whose
     * prescribed components the normal has a part along.
     */
    void set_contact_vertices(const unsigned int l, const BoundaryData &boundary);
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
     * The errors of set_contact_vertices(), over all processes: the first
     * unsupported roller vertex (@p unsupported, empty if none here) and
     * the largest penetration of a prescribed vertex. Collective.
     */
    void check_contact_vertices(const LevelData<dim> &data,
                                std::string           unsupported,
                                double                penetration) const;
    /** The rotation blocks and contact entities of level @p l. */
    void add_rotations(const unsigned int l, const BoundaryData &boundary);
    /**
     * The coupling pattern of level @p l for the rows held here, and the
     * import of its ghost rows.
     */
    void set_coupling_pattern(const unsigned int l);
    /** |n - e_1| below which the Householder reflection of n is I. */
    static constexpr double householder_tolerance = 1e-12;
    /**
     * A displacement prescribed at a contact vertex exceeds the gap when
     * u.n - g is above this times 1 + |u.n| + |g|: round-off of the data
     * (sin(pi) = 1.2e-16 against a gap of 0) passes.
     */
    static constexpr double penetration_round_off = 1e-12;

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
