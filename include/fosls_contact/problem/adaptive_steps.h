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
       * contact vertices and L2 on the contact boundary (HertzComparison).
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
       * sqrt(J) / sqrt(|u_ref - u_h|_H1^2 + |sigma_ref - sigma_h|_Hdiv^2)
       * (NaN without a reference).
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
    /** The errors of step @p s against the reference (the last row). */
    void set_reference_errors(const unsigned int s, const double u_h1, const double sigma_hdiv)
    {
      steps[s].reference_error_u_h1       = u_h1;
      steps[s].reference_error_sigma_hdiv = sigma_hdiv;
    }

    /**
     * Whether the adaptive loop goes on after the last step: not without
     * Adaptivity, after Adaptivity/Steps refinements, once sqrt(J) is at
     * most Adaptivity/Target sqrt(J), or after a solve that did not
     * converge; @p why says why not.
     */
    bool go_on(const Parameters::Adaptivity &adaptivity, std::string &why) const;

    /** A JSON array of one object per step. */
    std::string json() const;
    /** One CSV row per step, with a header. */
    std::string csv() const;

  private:
    std::vector<Step> steps;
  };
} // namespace FoslsContact

#endif
