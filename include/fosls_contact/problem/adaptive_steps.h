#ifndef fosls_contact_problem_adaptive_steps_h
#define fosls_contact_problem_adaptive_steps_h

#include <deal.II/base/types.h>

#include <fosls_contact/parameters/adaptivity.h>

#include <limits>
#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * What every solve of an adaptive run did, in the scene's units: the
   * table of the adaptive loop (FoslsProblem::run()), written to
   * summary.json ("adaptive_steps") and to adaptive_steps.csv, one row per
   * mesh. A uniform run is one step.
   */
  class AdaptiveSteps
  {
  public:
    struct Step
    {
      unsigned int            cells = 0;
      types::global_dof_index dofs  = 0;
      unsigned int            iterations = 0;
      /**
       * The solver's multigrid cycles (0 for the active set method) and
       * the times J went up (Monitor).
       */
      unsigned int            cycles = 0, energy_increases = 0;
      /** Solver/Cross check (FoslsProblem::cross_check()); NaN without. */
      double cross_check_functional = std::numeric_limits<double>::quiet_NaN();
      double cross_check_solution   = std::numeric_limits<double>::quiet_NaN();
      /** The wall time of the cross check's solve (0 without). */
      double time_cross_check_s = 0;
      bool                    converged  = false;
      /**
       * J, J of the solver's start (after the first step: the previous
       * solution carried over, projected), and the contact force (its
       * components).
       */
      double                  functional = 0, functional_start = 0;
      std::vector<double>     force;
      /** The solve's and the whole step's wall time (set-up to output). */
      double                  time_solve_s = 0, time_step_s = 0;
      /**
       * Hertz scenes: the relative error of the contact pressure, l2 at the
       * contact vertices and L2 on the contact boundary (HertzPressure).
       */
      double hertz_pressure_error          = std::numeric_limits<double>::quiet_NaN();
      double hertz_pressure_error_boundary = std::numeric_limits<double>::quiet_NaN();
      /** Scenes with an exact solution: |u - u_h|_H1 and |sigma - sigma_h|_Hdiv. */
      double error_u_h1       = std::numeric_limits<double>::quiet_NaN();
      double error_sigma_hdiv = std::numeric_limits<double>::quiet_NaN();
      /**
       * Adaptivity/Reference refinements: whether this row is the
       * reference (the last mesh refined everywhere), and for the rows
       * before it |u_ref - u_h|_H1 and |sigma_ref - sigma_h|_Hdiv (NaN
       * without a reference).
       */
      bool   reference                     = false;
      double reference_error_u_h1          = std::numeric_limits<double>::quiet_NaN();
      double reference_error_sigma_hdiv    = std::numeric_limits<double>::quiet_NaN();
      /**
       * The same error in the norm of the dimensionless problem
       * (ErrorNorms::scaled()), NaN without a reference.
       */
      double reference_error_scaled = std::numeric_limits<double>::quiet_NaN();
      /** J of the dimensionless problem, J / L^dim. */
      double functional_dimensionless = 0;
      /**
       * sqrt(J) over the solution's norm, both of the dimensionless
       * problem (RunSummary::add_error_estimate()).
       */
      double relative_error_estimate = std::numeric_limits<double>::quiet_NaN();
      /**
       * The largest von Mises stress, where it is and the diameter of
       * the cell there (Postprocessor::field_maxima()).
       */
      double              max_von_mises = 0;
      std::vector<double> von_mises_position;
      double              von_mises_cell_diameter = 0;
      /**
       * sqrt(J^) / (the error against the reference in the norm of the
       * dimensionless problem): dimensionless, the same in every unit
       * system (NaN without a reference).
       */
      double efficiency_index() const;
    };

    void add(const Step &step) { steps.push_back(step); }
    /** The wall time of the last step, from its assembly to its output. */
    void set_step_time(const double seconds) { steps.back().time_step_s = seconds; }
    /** The solve times of the steps so far, summed. */
    double total_solve_time() const
    {
      double sum = 0;
      for (const auto &s : steps)
        sum += s.time_solve_s;
      return sum;
    }
    unsigned int size() const { return steps.size(); }
    const Step & back() const { return steps.back(); }
    const Step & at(const unsigned int s) const { return steps.at(s); }
    /**
     * The errors of step @p s against the reference (the last row), in
     * the scene's units and (@p scaled) in the norm of the dimensionless
     * problem.
     */
    void set_reference_errors(const unsigned int s,
                              const double       u_h1,
                              const double       sigma_hdiv,
                              const double       scaled)
    {
      steps[s].reference_error_u_h1       = u_h1;
      steps[s].reference_error_sigma_hdiv = sigma_hdiv;
      steps[s].reference_error_scaled     = scaled;
    }

    /**
     * Whether the largest von Mises stress grew under the last two
     * refinements at one point, where @p text then says it: the stress is
     * singular there (a re-entrant corner, the edge of a bonded punch,
     * where the boundary conditions change), and its peak value is the
     * mesh's, not the body's (in @p stress_unit, Scaling/Unit names).
     */
    bool singular_stress(const std::string &stress_unit, std::string &text) const;

    /**
     * Whether the adaptive loop goes on after the last step: not without
     * Adaptivity, after Adaptivity/Steps refinements, once sqrt(J) is at
     * most Adaptivity/Target sqrt(J), or after a solve that did not
     * converge; @p why says why not.
     */
    bool go_on(const Parameters::Adaptivity &adaptivity, std::string &why) const;

    /** A JSON array of one object per step, of the first @p n steps. */
    std::string json(const unsigned int n) const;
    /** One CSV row per step, of the first @p n steps, with a header. */
    std::string csv(const unsigned int n) const;

  private:
    std::vector<Step> steps;
  };
} // namespace FoslsContact

#endif
