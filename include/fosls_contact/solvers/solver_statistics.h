#ifndef fosls_contact_solvers_solver_statistics_h
#define fosls_contact_solvers_solver_statistics_h

#include <fosls_contact/qp/matrix_list_memory.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace FoslsContact
{
  /** Wall time and number of calls of one part of a solve. */
  struct SectionTime
  {
    double       seconds = 0;
    unsigned int calls   = 0;
  };

  /**
   * Adds the wall time of its lifetime to a SectionTime, with a steady
   * clock and not with TimerOutput sections: entering and leaving a
   * TimerOutput section costs a mutex, lookups by string and a system call
   * for the CPU time, and the W-cycle enters some 30 per cycle: on the
   * small levels a measurable part of the solve (doc/performance.md,
   * section 3, MultigridCounters).
   */
  class ScopedTime
  {
  public:
    explicit ScopedTime(SectionTime &time)
      : time(time)
      , start(std::chrono::steady_clock::now())
    {}
    ~ScopedTime()
    {
      time.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ++time.calls;
    }
    ScopedTime(const ScopedTime &) = delete;
    ScopedTime &operator=(const ScopedTime &) = delete;

  private:
    SectionTime &                         time;
    std::chrono::steady_clock::time_point start;
  };

  /**
   * What the monotone multilevel method counts and times while it runs,
   * filled in by its parts (MonotoneCycle, NewtonStep, PatchSmoother,
   * LevelOperators, CoarseSolver).
   */
  struct MultigridCounters
  {
    /** The patch sweeps, on every level. */
    SectionTime smoothing;
    /**
     * The truncated prolongations, the Galerkin products and the set-up
     * of the patch smoother for their operators (of the finest level too).
     */
    SectionTime operators;
    /** The exact solves of the coarsest level a cycle visits. */
    SectionTime coarse_solve;
    /** The visits of every level by the cycles, with the coarser levels. */
    std::vector<SectionTime> level_visits;
    /** Coarse corrections that increased J beyond round-off. */
    unsigned int energy_increases = 0;
    /** Coarse corrections shortened to stay feasible. */
    unsigned int feasibility_dampings = 0;
    /** Solver/Check coarse defects: MonotoneCycle::check_coarse_defect(). */
    unsigned int coarse_defect_checks     = 0;
    double       coarse_defect_difference = 0;
    /**
     * The CG steps of the Newton steps' linear solves, each one linear
     * cycle as the preconditioner, and the sum of the natural logarithms
     * of the solves' residual reductions (SolverControl's last value over
     * its initial one): the linear cycle's mean rate
     * (SolverStatistics::Multilevel::linear_rate()).
     */
    unsigned long long linear_steps         = 0;
    double             linear_log_reduction = 0;
  };

  /** What a solver reports of a solve beyond its iterates (summary.json). */
  struct SolverStatistics
  {
    /** The wall time of the parts of solve() (inside "Solve"), by name. */
    std::map<std::string, SectionTime> sections;

    /** The monotone multilevel method's own figures. */
    struct Multilevel
    {
      /**
       * The number of patch colors of levels 1..finest: the barriers of
       * the threads and the ghost exchanges of one smoothing step per
       * level.
       */
      std::vector<unsigned int> patch_colors;
      /** The DoFs of every level 0..finest. */
      std::vector<unsigned long long> level_dofs;
      /**
       * The visits of every level by the cycles (those of the coarsest
       * level the cycle reaches are exact solves: level 0, or a finer one
       * in the linear cycle, whose coarser levels then have no visits) and
       * their wall time without that of the coarser levels they visit:
       * where a cycle's time goes (bench/level_costs.py).
       */
      std::vector<SectionTime> level_times;
      /**
       * The patch sweeps over every level 0..finest (pre- and
       * post-smoothing, in the cycles and in the Newton steps' projected
       * smoothing). A sweep over level l costs about level_dofs[l] /
       * level_dofs[finest] of one over the finest level, the work unit of
       * multigrid (Brandt): their sum is the work of the solve in fine
       * sweeps (work_units()).
       */
      std::vector<unsigned long long> level_sweeps;
      /** The sweeps of level_sweeps in sweeps over the finest level. */
      double
      work_units() const
      {
        double work = 0;
        for (unsigned int l = 0; l < level_sweeps.size(); ++l)
          work += double(level_sweeps[l]) * double(level_dofs[l]) / double(level_dofs.back());
        return work;
      }
      /**
       * With Solver/Check coarse defects: the number of second visits that
       * took their coarse defect from the first visit's, and the largest
       * difference to the recomputed one. Both 0 without the check.
       */
      unsigned int coarse_defect_checks     = 0;
      double       coarse_defect_difference = 0;
      /** MultigridCounters::linear_steps and linear_log_reduction. */
      unsigned long long linear_steps         = 0;
      double             linear_log_reduction = 0;
      /**
       * The residual reduction per linear cycle of the Newton steps' CG
       * solves, their geometric mean over all their steps (the rate the
       * linear cycle gives CG: independent of the level where multigrid
       * works as it should); NaN without a linear solve.
       */
      double
      linear_rate() const
      {
        return linear_steps > 0 ? std::exp(linear_log_reduction / double(linear_steps)) :
                                  std::numeric_limits<double>::quiet_NaN();
      }
      /**
       * The bytes this process holds in the solver's structures, by
       * structure (memory_consumption() of each) and level: what the solve
       * adds to the memory of the assembled problem.
       */
      std::vector<std::pair<std::string, LevelBytes>> memory;
    };
    std::optional<Multilevel> multilevel;
  };
} // namespace FoslsContact

#endif
