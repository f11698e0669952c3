#ifndef fosls_contact_solvers_monitor_h
#define fosls_contact_solvers_monitor_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/iteration_observer.h>
#include <fosls_contact/solvers/iteration_record.h>
#include <fosls_contact/solvers/stopping_rules.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace FoslsContact
{
  /**
   * The one place where solvers report (their IterationObserver): every
   * solver calls report() after each iteration, and the monitor computes J
   * and its parts, the correction, the rate, the active set and the
   * violation, prints one line, decides whether to stop, and later writes
   * convergence.csv. Solvers therefore never print on their own and all
   * stop by the same rule.
   */
  class Monitor : public IterationObserver
  {
  public:
    Monitor(const ConstrainedQP &        qp,
            const Parameters::Solver &   parameters,
            const ConditionalOStream &   pcout,
            const std::string &          solver_name);

    /** Record the starting iterate as iteration 0. */
    void start(const LevelVector &x) override;

    /**
     * Record iteration @p x (after @p x_old); print; return true when the
     * stopping criterion is met or the iteration limit is reached
     * (converged() tells which).
     */
    bool report(const LevelVector &x, const LevelVector &x_old) override;

    /** A solver found J(new) > J(old) at @p n sub-steps. */
    void note_energy_increases(const unsigned int n) override { n_energy_increases += n; }
    /** A solver applied @p n multigrid cycles (on the finest level). */
    void note_cycles(const unsigned int n) override { n_cycles += n; }
    unsigned int cycles() const { return n_cycles; }
    /**
     * Mean error reduction per cycle over the run:
     * (|dx_last|_A / |dx_1|_A)^(1 / cycles after the first iteration).
     */
    double rate_per_cycle() const;
    /**
     * The corrections' reduction per iteration, as a sum to combine runs
     * (the Tresca problems of a load step): the logarithm of
     * |dx_last|_A / |dx_1|_A and the number of iterations it took, with
     * the last iteration the last one above the round-off floor (as for
     * rate_per_cycle()); {0, 0} if none after the first is above it.
     */
    std::pair<double, unsigned int> measured_reduction() const;

    /** A solver had to shorten @p n coarse corrections to stay feasible. */
    void note_feasibility_dampings(const unsigned int n) override
    {
      n_feasibility_dampings += n;
    }

    /**
     * For solvers that detect convergence themselves (the active set
     * method at its KKT point, the multigrid on one level): stop_reason()
     * is then "exact".
     */
    void set_converged() override
    {
      has_converged = true;
      reason        = "exact";
    }

    /**
     * A stop short of convergence that the caller decides (the Coulomb
     * fixed point out of its iterations, FoslsProblem::solve()):
     * why_not_converged() gives "not converged: " and @p why.
     */
    void set_not_converged(const std::string &why)
    {
      has_converged     = false;
      reason            = "fixed point";
      not_converged_why = why;
    }

    /**
     * A lower bound for the first correction that Solver/Tolerance is
     * relative to. The Coulomb fixed point (FoslsProblem::solve()) gives
     * each Tresca problem after a load step's first the first correction
     * of that first one: these problems start next to their solution, and
     * a factor 1e-8 of their own first correction, which shrinks with the
     * fixed point's change of the slip bounds, lies below the round-off
     * floor of the corrections, so that every problem ran until the
     * monitor found that floor, more iterations the finer the mesh
     * (doc/method.md, section 7.7, "Stopping").
     */
    void set_reference_correction(const double correction) { reference_correction = correction; }
    /**
     * A lower bound @p rho for the rate the stopping criterion
     * "discretization accuracy" estimates the algebraic error with: the
     * rate a nested iteration's coarser levels measured
     * (InitialGuessRecord::rate), for a level that starts so close to
     * its solution that its own first rates say little.
     */
    void set_rate_floor(const double rho) { rate_floor = rho; }
    /**
     * The stopping criterion "discretization accuracy" waits for @p n
     * rates in the linear phase (1 by default) before it trusts the
     * largest of them: the coarser levels of a nested iteration, whose
     * rates the finer levels take as their floor. Two corrections alone
     * can hide a slow method: after a large first correction the second
     * may be small while the iteration creeps (doc/method.md, section 7.5).
     */
    void require_rates(const unsigned int n) { minimum_rates = n; }
    /**
     * The largest rate since the active set last changed (the rate the
     * stopping criterion "discretization accuracy" used; 0 before the
     * second iteration).
     */
    double linear_rate() const;
    /** The energy norm of the first correction (0 before it). */
    double first_correction() const { return history.size() > 1 ? history[1].correction : 0.; }
    /**
     * What the tolerance is relative to: the first correction, or the
     * reference correction where that is larger.
     */
    double tolerance_reference() const
    {
      return std::max({first_correction(), reference_correction, 1e-300});
    }

    /**
     * Let report() end a run that stalls (a solver whose rate is steady
     * once the active set settles: the monotone multigrid). A stall is
     * stall_window iterations with the active set unchanged, every rate
     * between stall_rate and 1/stall_rate and every correction far above
     * its round-off floor, at whose mean rate rho the estimated error
     * (rho/(1 - rho) times the correction) would need more than
     * stall_excess times the iterations left to reach the stopping rule's
     * target. Such a run ends as not converged, stop_reason() "stalled".
     */
    void enable_stall_detection() override { detect_stalls = true; }

    /**
     * J may grow from one iteration to the next by this much, relative, and
     * still count as the round-off of its evaluation (J is summed in twice
     * the working precision, ConstrainedQP::parts()).
     */
    static constexpr double divergence_tolerance = 1e-6;
    /**
     * Whether the last iteration of a descent method (one that called
     * enable_divergence_detection()) increased J beyond
     * divergence_tolerance: report() then ends the run as not converged,
     * stop_reason() "diverged".
     */
    bool diverged() const;
    void enable_divergence_detection() override { detect_divergence = true; }

    unsigned int energy_increases() const { return n_energy_increases; }
    /** Whether the run stopped at the round-off floor of the corrections. */
    bool stopped_at_round_off() const { return at_floor; }
    unsigned int feasibility_dampings() const { return n_feasibility_dampings; }
    unsigned int iterations() const { return history.size() - 1; }
    bool         converged() const override { return has_converged; }
    /**
     * Why the run stopped: "tolerance", "discretization accuracy" (the
     * stopping criteria), "round-off floor" (the corrections reached it),
     * "exact" (set_converged()), all converged; "stalled" or "iteration
     * limit", not converged; "" while it runs.
     */
    const std::string &stop_reason() const { return reason; }
    /**
     * "" if converged, else why not in a few words (the stall's rate, the
     * iteration in which J grew, or Solver/Max iterations), for the one
     * line the program ends with.
     */
    std::string why_not_converged() const;
    /**
     * For a run that stalled: its estimated error over the stopping rule's
     * target when it stopped.
     */
    double stalled_error_ratio() const { return stall_error; }
    const std::vector<IterationRecord> &get_history() const { return history; }

    /** Geometric mean of the rates of the last (up to) 5 iterations. */
    double asymptotic_rate() const;

    /** CSV text of the history (the caller writes it atomically). */
    std::string csv() const;

    const std::string &name() const { return solver_name; }

    /**
     * Print and write J (and the energy norms of the corrections, times
     * the square root) multiplied by @p factor: the solvers work on the
     * dimensionless functional, the user reads it in the scene's units
     * (ReferenceScales::functional()). The stopping rule is relative and does not
     * see it.
     */
    void set_functional_unit(const double factor) { functional_unit = factor; }

  private:
    /** The last iteration whose correction lies above the round-off floor (at least 2). */
    unsigned int last_measured_iteration() const;
    /**
     * The record of iteration @p x (after @p x_old), appended to the
     * history (with the round-off floor of the corrections at @p x:
     * ConstrainedQP::measure() reads A once for all of them); the active
     * set's last change.
     */
    const IterationRecord &record(const LevelVector &x, const LevelVector &x_old);
    /**
     * Whether the last correction is at the round-off floor of the
     * corrections at its iterate (the record's round_off:
     * ConstrainedQP::round_off_correction()), with the rate @p rho and the
     * error factor @p factor = max(1, rho/(1 - rho)), or the corrections
     * stagnate above it (StoppingRules).
     */
    bool at_round_off_floor(const double rho, const double factor);
    const ConstrainedQP &         qp;
    const Parameters::Solver      parameters;
    const ConditionalOStream &    pcout;
    const std::string             solver_name;
    const StoppingRules           rules;
    std::vector<IterationRecord>  history;
    /**
     * The active set of the last iterate (owned DoFs), and the iteration
     * it last changed (on any process).
     */
    std::vector<bool>             active_set;
    unsigned int                  active_set_changed_at  = 0;
    Timer                         timer;
    unsigned int                  n_energy_increases     = 0;
    unsigned int                  n_feasibility_dampings = 0;
    unsigned int                  n_cycles               = 0;
    unsigned int                  cycles_after_first     = 0;
    bool                          has_converged          = false;
    bool                          at_floor               = false;
    bool                          floor_stagnated        = false;
    double                        functional_unit        = 1.;
    bool                          detect_stalls          = false;
    bool                          detect_divergence      = false;
    std::string                   reason;
    double                        stall_error            = 0;
    double                        reference_correction   = 0;
    double                        rate_floor             = 0;
    unsigned int                  minimum_rates          = 1;
    /** set_not_converged()'s reason. */
    std::string not_converged_why;
  };
} // namespace FoslsContact

#endif
