#ifndef fosls_contact_discretization_discretization_h
#define fosls_contact_discretization_discretization_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/scene/scene.h>

#include <map>

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
   * `dofs`. The first rotated coordinate is the normal one.
   */
  template <int dim>
  struct RotationBlock
  {
    std::array<types::global_dof_index, dim> dofs;
    FullMatrix<double>                       matrix;
    FullMatrix<double>                       inverse;
  };

  /** A contact vertex on one level: u.n <= g bounds DoF `normal_dof`. */
  template <int dim>
  struct ContactVertex
  {
    unsigned int             vertex_index;
    types::global_dof_index  normal_dof;
    Point<dim>               point;
    Tensor<1, dim>           normal;
    double                   gap;
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
  };

  /**
   * Everything the algebra needs to know about one level: its DoF roles,
   * the values of fixed DoFs and the upper bounds (both in the rotated
   * basis), the rotations, and the contact entities.
   */
  template <int dim>
  struct LevelData
  {
    types::global_dof_index                 n_dofs = 0;
    std::vector<DoFRole>                    role;
    Vector<double>                          fixed_values;
    Vector<double>                          upper_bounds;
    std::vector<RotationBlock<dim>>         rotations;
    /** For each DoF, the index of its rotation block, or invalid. */
    std::vector<unsigned int>               rotation_of_dof;
    std::vector<ContactVertex<dim>>         contact_vertices;
    std::vector<ContactFace<dim>>           contact_faces;
    /** vertex index -> its displacement DoFs (component by component). */
    std::map<unsigned int, std::array<types::global_dof_index, dim>> vertex_dofs;
    /** face index -> its RT DoFs (stress row by row). */
    std::map<unsigned int, std::array<types::global_dof_index, dim>> face_dofs;
    SparsityPattern                         sparsity;
  };

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
   */
  template <int dim>
  class Discretization
  {
  public:
    Discretization(const Scene<dim> &scene, const unsigned int n_levels);

    const Triangulation<dim> &get_triangulation() const { return triangulation; }
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
     * active numbering (for DataOut and error integration).
     */
    Vector<double> to_active(const Vector<double> &level_vector) const;

    /** x_cartesian = R x_rotated on level @p l. */
    void rotate_to_cartesian(const unsigned int l, Vector<double> &x) const;
    /** x_rotated = R^{-1} x_cartesian on level @p l. */
    void rotate_to_normal_tangential(const unsigned int l, Vector<double> &x) const;

    /** The Householder reflection H with H e_1 = n (paper section 4.3). */
    static FullMatrix<double> householder(const Tensor<1, dim> &n);

  private:
    void setup_level(const unsigned int l);
    /** x <- R x (or R^{-1} x) block by block on level @p l. */
    void apply_rotations(const unsigned int l,
                         Vector<double> &   x,
                         const bool         inverse) const;

    const Scene<dim> &      scene;
    Triangulation<dim>      triangulation;
    FESystem<dim>           fe;
    MappingQ<dim>           mapping;
    DoFHandler<dim>         dof_handler;
    std::vector<LevelData<dim>> levels;
    double                  coarse_ratio = 1;
  };
} // namespace FoslsContact

#endif
