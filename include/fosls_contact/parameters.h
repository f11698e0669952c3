#ifndef fosls_contact_parameters_h
#define fosls_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * All run-time parameters, one struct per subsection of the input file.
   *
   * Every struct has the same two functions: `declare_parameters()` adds its
   * entries (with a Patterns object, so that ParameterHandler rejects a bad
   * value with the name of the entry) and `parse_parameters()` reads them back
   * and performs the checks that a Pattern cannot express (e.g. `lambda =
   * inf`). Errors are thrown as ExcMessage with a one-line text that names the
   * parameter; main() adds the file name.
   */
  namespace Parameters
  {
    /**
     * subsection Geometry: which mesh, how fine, how many levels. The
     * coarse mesh is a box, one of the built-in curved bodies (half disc,
     * half ball, half cylinder), or read from a mesh file.
     */
    struct Geometry
    {
      enum class Shape
      {
        box,
        half_disc,
        half_ball,
        half_cylinder,
        file,
      };

      /**
       * A curved surface that the faces of one boundary id lie on
       * (`Geometry/Manifolds`): refinement puts the new vertices of these
       * faces on it. In the scene's units.
       */
      struct Manifold
      {
        enum class Kind
        {
          sphere,   ///< a circle in 2D: center and radius
          cylinder, ///< 3D: a point on the axis, the axis' direction, radius
        };
        unsigned int        boundary_id = 0;
        Kind                kind        = Kind::sphere;
        std::vector<double> point;     ///< the center, or a point on the axis
        std::vector<double> direction; ///< the axis (cylinder only)
        double              radius = 0;
        /** The entry as written, for messages. */
        std::string text;
      };

      unsigned int        dimension = 2;
      Shape               shape     = Shape::box;
      std::vector<double> lower_corner;
      std::vector<double> upper_corner;
      std::vector<unsigned int> subdivisions;
      double              radius       = 0.5;
      std::vector<double> center;
      /** Length of the half cylinder (along z). */
      double              length = 1.;
      /** Cells of the half cylinder's coarse mesh along its axis. */
      unsigned int        length_subdivisions = 2;
      unsigned int        coarse_refinements  = 2;
      double              grading             = 1.0;
      /** The mesh file, resolved by ParameterReader (Shape = file). */
      std::string           mesh_file;
      std::vector<Manifold> manifolds;
      /** Number of multigrid levels J (the coarse mesh is level 1). */
      unsigned int levels = 5;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);

    private:
      void parse_manifolds(const std::string &text);
    };

    /**
     * subsection Material: the elastic constants, given either as the Lame
     * parameters (mu, lambda) or as Young's modulus and Poisson's ratio
     * (E, nu), exactly one of the two pairs, in any consistent units. The
     * other pair is computed; lambda = inf and nu = 0.5 are the
     * incompressible material.
     */
    struct Material
    {
      double mu     = 1.;
      double lambda = 1.; ///< +infinity for incompressible material
      double youngs_modulus = 2.5;  ///< E
      double poisson_ratio  = 0.25; ///< nu

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /**
     * subsection Scaling: the reference length L and stress S that make the
     * problem dimensionless (doc/method.md, section 1). A value of 0 means
     * "derive it": L from the coarse mesh (the largest side of its bounding
     * box), S = mu.
     */
    struct Scaling
    {
      double reference_length = 0.;
      double reference_stress = 0.;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /** subsection Functional weights: C_eq, C_const, C_compl of eq. (1)-(2). */
    struct Weights
    {
      double c_eq    = 1e2;
      double c_const = 1.;
      double c_compl = 0.1;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /**
     * subsection Data: the functions of a scene, as FunctionParser
     * expressions in x, y (, z). Components are separated by `;`. An empty
     * body force means the scene has none: no term is assembled for it.
     */
    struct Data
    {
      std::string body_force;
      std::string dirichlet_values;
      std::string traction;
      std::string gap;
      std::string obstacle_normal;
      std::string exact_displacement;
      std::string exact_stress;
      std::string initial_displacement;
      std::string constants;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /**
     * subsection Boundary conditions: which boundary ids are Dirichlet,
     * Neumann and contact boundaries. Every boundary id of the mesh must be
     * named exactly once. On a Dirichlet id, the components not listed in
     * `Dirichlet components` get the traction of the Neumann data instead
     * (a roller), component by component. The components may differ per
     * id ("0: 0; 3: all"): a symmetry plane beside a clamped side, whose
     * rigid motions the clamped side fixes.
     */
    struct BoundaryConditions
    {
      std::vector<unsigned int> dirichlet_ids;
      /// per Dirichlet id: which components are prescribed (size dim);
      /// filled by AllParameters::parse_parameters, which knows dim
      std::map<unsigned int, std::vector<bool>> dirichlet_components;
      std::string               dirichlet_components_text = "all";
      std::vector<unsigned int> neumann_ids;
      std::vector<unsigned int> contact_ids;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /** subsection Solver. */
    struct Solver
    {
      enum class Type
      {
        monotone_multigrid,
        active_set,
        projected_gauss_seidel,
      };
      enum class Projection
      {
        a,
        b,
        c,
        d,
      };
      enum class InitialGuess
      {
        zero,
        coarse_solution,
        nested_iteration,
        expression,
      };
      enum class Stopping
      {
        tolerance,
        discretization_accuracy,
      };
      /**
       * V: one visit of the coarser level per visit; W: two; F: an F-cycle
       * on the coarser level, then a V-cycle there (level l - k is visited
       * k + 1 times instead of 2^k).
       */
      enum class Cycle
      {
        V,
        W,
        F,
      };

      /**
       * The Newton step's linear truncated cycle: the own MonotoneCycle,
       * or the same cycle run by deal.II's Multigrid (LinearMultigrid).
       */
      enum class LinearCycle
      {
        own,
        dealii,
      };

      Type         type                = Type::monotone_multigrid;
      double       tolerance           = 1e-8;
      unsigned int max_iterations      = 200;
      Stopping     stopping            = Stopping::tolerance;
      double       discretization_fraction = 0.1;
      unsigned int pre_smoothing       = 3;
      unsigned int post_smoothing      = 3;
      Cycle        cycle               = Cycle::W;
      Projection   projection          = Projection::b;
      InitialGuess initial_guess       = InitialGuess::coarse_solution;
      unsigned int definiteness_max_dofs = 20000;
      unsigned int krylov_steps          = 50;
      LinearCycle  linear_cycle          = LinearCycle::own;
      /** 0: as many threads as cores (or DEAL_II_NUM_THREADS). */
      unsigned int threads               = 0;
      /**
       * A diagnostic: recompute the coarse defects a W- or F-cycle's
       * second visit takes from the first (MonotoneCycle) and
       * report the largest difference.
       */
      bool         check_coarse_defects  = false;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /** subsection Output. */
    struct Output
    {
      std::string directory = "output";
      bool        write_vtu = true;
      bool        verbose   = true;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /**
     * subsection Hertz comparison: a scene that is a Hertz contact (a
     * cylinder, per unit length in 2D, or a sphere, in 3D, of radius R
     * against a plane, one of them rigid) declares it here, and the run
     * compares its contact pressure with Hertz's (HertzComparison).
     */
    struct HertzComparison
    {
      enum class Shape
      {
        none,
        cylinder,
        sphere,
      };
      Shape               shape  = Shape::none;
      double              radius = 0;
      /** The first point of contact, where Hertz's pressure peaks. */
      std::vector<double> contact_point;
      /**
       * The full contact's force per computed force: 4 for a quarter model
       * of a sphere, 2 for a half model; Hertz's formulas get the full
       * force.
       */
      double              force_factor = 1.;
      /** A cylinder in 3D: the direction of its axis. */
      std::vector<double> axis;
      /** A cylinder in 3D: the length of the contact line (of the full model). */
      double              length = 0.;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /** All subsections together. */
    struct AllParameters
    {
      Geometry           geometry;
      Material           material;
      Scaling            scaling;
      Weights            weights;
      Data               data;
      BoundaryConditions boundary_conditions;
      Solver             solver;
      Output             output;
      HertzComparison    hertz;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };

    /** Parse a double that may be written `inf`. */
    double parse_extended_double(const std::string &text, const std::string &name);
    /** Parse a comma separated list of doubles. */
    std::vector<double> parse_double_list(const std::string &text);
    /**
     * A body of size @p size at distance @p distance from the origin has
     * vertex coordinates that must resolve the cells of the finest level
     * (size / 2^13 with 14 levels) in double precision: refuse a size
     * below 1e-6 of the distance, naming @p what, instead of meeting
     * degenerate cells later. (Any size itself is fine: the program works
     * in units of the body's size, Scaling.)
     */
    void check_resolvable(const double size, const double distance, const std::string &what);
  } // namespace Parameters
} // namespace FoslsContact

#endif
