#ifndef fosls_contact_scene_scene_h
#define fosls_contact_scene_scene_h

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/grid/tria.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/scene/mesh_file.h>
#include <fosls_contact/scene/scaled_function.h>
#include <fosls_contact/scene/reference_scales.h>

#include <map>
#include <memory>
#include <set>

namespace FoslsContact
{
  /**
   * A scene: the geometry (coarse mesh with boundary ids) and the data
   * functions of one problem, read from the parameter file.
   *
   * The scene is given in the user's units; the scene hands the rest of
   * the program its dimensionless form (ReferenceScales, doc/method.md section 1):
   * the coarse mesh in units of the reference length L, the data
   * functions divided by their scales, the elastic constants divided by
   * the reference stress S. Only the output converts back.
   *
   * The scene also decides which effects exist. A body force is simulated
   * only when the file gives one, and contact only when it names contact
   * boundary ids; everything downstream asks has_body_force() and
   * has_contact() instead of assembling zero terms, so an undeclared effect
   * costs nothing.
   */
  template <int dim>
  class Scene
  {
  public:
    explicit Scene(const Parameters::AllParameters &parameters);

    /**
     * Fill @p triangulation with the dimensionless coarse mesh (level 1 of
     * the paper, level 0 in deal.II: the scene's mesh divided by L) and
     * check that its boundary ids are exactly the ones named in the
     * parameter file.
     */
    void make_coarse_mesh(Triangulation<dim> &triangulation) const;

    /**
     * Take the constants of load step @p step (Data/Load steps,
     * Parameters::Data::step_overrides()) and parse the data expressions
     * with them anew: the data functions are those of that step, and a
     * Discretization built on the scene takes them with
     * Discretization::update_data(). Step 0 of a run without load steps
     * is the scene as constructed.
     */
    void set_load_step(const Parameters::AllParameters &parameters, const unsigned int step);

    /** The value of the constant @p name (Data/Constants) at the current step. */
    double constant(const std::string &name) const { return constants.at(name); }

    /** The reference length and stress of this scene. */
    const ReferenceScales &scaling() const { return reference; }
    /**
     * The dimensionless elastic constants: mu/S and lambda/S (E/S and nu
     * as well).
     */
    const Parameters::Material &material() const { return dimensionless_material; }

    bool has_contact() const { return !contact_ids.empty(); }
    bool has_body_force() const { return body_force_function != nullptr; }
    bool has_exact_solution() const { return exact_u_function != nullptr; }
    /** The friction law (Friction/Law); none: frictionless contact. */
    Parameters::Friction::Law friction_law() const { return friction; }
    bool has_friction() const { return friction != Parameters::Friction::Law::none; }

    bool is_dirichlet(const types::boundary_id id) const;
    bool is_neumann(const types::boundary_id id) const;
    bool is_contact(const types::boundary_id id) const;
    /** Components of u prescribed on the Dirichlet id @p id. */
    const std::vector<bool> &dirichlet_components(const types::boundary_id id) const
    {
      return dirichlet_masks.at(id);
    }

    /** @{ The data at dimensionless points, dimensionless. */
    const ScaledFunction<dim> &body_force() const { return *body_force_scaled; }
    const ScaledFunction<dim> &dirichlet_values() const { return *dirichlet_scaled; }
    const ScaledFunction<dim> &traction() const { return *traction_scaled; }
    const ScaledFunction<dim> &gap() const { return *gap_scaled; }
    /**
     * With friction: Tresca's slip bound s (dimensionless, a stress) or
     * Coulomb's coefficient f, by friction_law().
     */
    const ScaledFunction<dim> &friction_data() const { return *friction_scaled; }
    /** The unit obstacle normal at the dimensionless point @p p. */
    Tensor<1, dim> obstacle_normal(const Point<dim> &p) const;
    /** Initial displacement expression, or null. */
    const Function<dim> *initial_displacement() const
    {
      return initial_u_scaled.get();
    }
    /** @} */

    /** @{ The data in the scene's units, at points in the scene's units. */
    const Function<dim> &body_force_in_scene_units() const { return *body_force_function; }
    const Function<dim> &exact_displacement() const { return *exact_u_function; }
    /** Exact stress, dim*dim components, row by row; may be null. */
    const Function<dim> *exact_stress() const { return exact_sigma_function.get(); }
    /** @} */

    /**
     * Refuse a mesh with a cell whose corner has a Jacobian determinant
     * <= 0 on any level (a graded half disc bent too far, a twisted cell
     * of a mesh file, a file mesh's manifold that pulls a refined boundary
     * vertex through its cell; CellShapeCheck). Collective on @p comm.
     */
    void check_cell_shapes(const Triangulation<dim> &tria, const MPI_Comm comm) const;

    /** h_max / h_min of the coarse mesh, printed for graded meshes. */
    static double mesh_size_ratio(const Triangulation<dim> &triangulation);

  private:
    /**
     * The mesh of Geometry/Mesh file, for Shape = file: read on every
     * process, so that one that cannot (the file missing on its node)
     * stops them all (CollectiveError) instead of leaving them waiting.
     */
    void read_mesh_file();
    /**
     * The reference length and stress, checked against the range in which
     * the areas, volumes and forces converted back with them stay finite,
     * and the material in their units.
     */
    void set_reference_units(const Parameters::AllParameters &prm);
    /**
     * The constants of Data/Constants (@p definitions, "name=value, ..."),
     * with pi; a name muparser cannot take (a coordinate, no identifier,
     * given twice) is refused here, where muparser would crash.
     */
    void read_constants(const std::string &definitions);
    /**
     * The data functions the scene uses, in its units, and their
     * dimensionless versions; the others are zero, so that an expression
     * the scene does not need is never parsed.
     */
    void make_data_functions(const Parameters::AllParameters &prm);

    /** The data expression of parameter @p name (DataExpression). */
    std::unique_ptr<FunctionParser<dim>>
    make_function(const std::string &expression,
                  const unsigned int n_components,
                  const std::string &name) const;
    /** L: the parameter, or the largest side of the coarse mesh's box. */
    double reference_length(const Parameters::AllParameters &parameters) const;

    const Parameters::Geometry geometry;
    /** The mesh of Geometry/Mesh file (Shape = file), in the scene's units. */
    std::unique_ptr<const MeshFile<dim>> mesh_file;
    ReferenceScales            reference;
    Parameters::Material       dimensionless_material;
    std::map<std::string, double> constants;
    std::set<types::boundary_id> dirichlet_ids, neumann_ids, contact_ids;
    std::map<unsigned int, std::vector<bool>> dirichlet_masks;

    std::unique_ptr<FunctionParser<dim>> body_force_function;
    std::unique_ptr<FunctionParser<dim>> dirichlet_function;
    std::unique_ptr<FunctionParser<dim>> traction_function;
    std::unique_ptr<FunctionParser<dim>> gap_function;
    std::unique_ptr<FunctionParser<dim>> normal_function;
    std::unique_ptr<FunctionParser<dim>> exact_u_function;
    std::unique_ptr<FunctionParser<dim>> exact_sigma_function;
    std::unique_ptr<FunctionParser<dim>> initial_u_function;
    std::unique_ptr<FunctionParser<dim>> friction_function;
    Parameters::Friction::Law            friction = Parameters::Friction::Law::none;

    std::unique_ptr<ScaledFunction<dim>> body_force_scaled, dirichlet_scaled,
      traction_scaled, gap_scaled, initial_u_scaled, friction_scaled;
  };
} // namespace FoslsContact

#endif
