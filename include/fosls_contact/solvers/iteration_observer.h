#ifndef fosls_contact_solvers_iteration_observer_h
#define fosls_contact_solvers_iteration_observer_h

#include <fosls_contact/qp/level_algebra.h>

namespace FoslsContact
{
  /**
   * What a QPSolver reports its progress to, and what decides when it
   * stops: start() with the starting iterate, report() after every
   * iteration, whose answer ends the run, and the counts of the events
   * inside an iteration (note_*). The program's Monitor implements it
   * (screen lines, convergence.csv, the stopping rule), so that every
   * solver stops by the same rule and none prints on its own.
   */
  class IterationObserver
  {
  public:
    virtual ~IterationObserver() = default;

    /** The starting iterate (iteration 0). */
    virtual void start(const LevelVector &x) = 0;
    /**
     * Iteration @p x after @p x_old; true when the run is to stop (the
     * stopping rule is met, converged(), or it is not going to be).
     */
    virtual bool report(const LevelVector &x, const LevelVector &x_old) = 0;
    /** Whether the last report() found the run converged. */
    virtual bool converged() const = 0;
    /**
     * For a solver that knows it has the exact solution (the active set
     * method at its KKT point, the multigrid on one level).
     */
    virtual void set_converged() = 0;
    /**
     * For a solver whose rate is steady once the active set settles (the
     * monotone multigrid): let report() end a run that stalls.
     */
    virtual void enable_stall_detection() = 0;
    /**
     * For a descent method (projected Gauss-Seidel, the monotone
     * multigrid), whose steps never increase J: let report() end a run
     * whose J grows.
     */
    virtual void enable_divergence_detection() = 0;

    /** The iteration applied @p n multigrid cycles (on the finest level). */
    virtual void note_cycles(const unsigned int n) = 0;
    /** @p n sub-steps of the iteration increased J beyond round-off. */
    virtual void note_energy_increases(const unsigned int n) = 0;
    /** @p n coarse corrections were shortened to stay feasible. */
    virtual void note_feasibility_dampings(const unsigned int n) = 0;
  };
} // namespace FoslsContact

#endif
