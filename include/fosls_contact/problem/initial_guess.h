#ifndef fosls_contact_problem_initial_guess_h
#define fosls_contact_problem_initial_guess_h

#include <deal.II/base/conditional_ostream.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/scene.h>

#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * What an initial guess hands to the run besides the start itself: the
   * work and the rates of a nested iteration's solves on the coarser
   * levels (all zero or empty for the other guesses).
   */
  struct InitialGuessRecord
  {
    /** What one coarser level's solve of a nested iteration did. */
    struct LevelSolve
    {
      unsigned int            level;
      types::global_dof_index dofs;
      unsigned int            iterations;
      unsigned int            cycles;
      /** Monitor::stop_reason() */
      std::string stop_reason;
      /** Monitor::linear_rate() */
      double linear_rate;
      /** J's increases (Monitor::energy_increases(); 0: J monotone) */
      unsigned int energy_increases;
      bool         converged;
    };

    /**
     * The patch sweeps of the solves on coarser levels, in sweeps over the
     * finest level: the work the guess adds to the solve's
     * (SolverStatistics::Multilevel::work_units()).
     */
    double work_units = 0;
    /**
     * The largest rate those solves measured in their linear phase
     * (Monitor::linear_rate()): the finest level's solve, which starts
     * next to its solution, estimates its algebraic error with at least
     * this rate (Monitor::set_rate_floor()).
     */
    double rate = 0;
    /** The solves on levels 1 .. finest - 1. */
    std::vector<LevelSolve> level_solves;

    /** level_solves as a JSON array (summary.json's `nested_iteration`). */
    std::string level_solves_json() const;
  };


  /**
   * The start of the solve on the finest level (Solver/Initial guess):
   * zero, the exact solution of level 1 interpolated (paper section 7),
   * nested iteration over the levels, or Data/Initial displacement. The
   * two level-wise guesses assemble and solve coarser problems and carry
   * rotated vectors between levels, work of its own beside the solve.
   */
  template <int dim>
  class InitialGuess
  {
  public:
    InitialGuess(const Parameters::AllParameters &parameters,
                 const Scene<dim> &               scene,
                 const Discretization<dim> &      discretization,
                 const LevelTransfer<dim> &       transfer,
                 const ConditionalOStream &       pcout);

    /**
     * The initial guess for @p qp, the finest level's problem, in
     * @p solution (rotated); notes a start that violates the contact
     * constraints (the solver projects it).
     */
    void compute(const ConstrainedQP &qp, LevelVector &solution);

    /** The last compute()'s record (nested iteration's work and rates). */
    const InitialGuessRecord &record() const { return guess_record; }

  private:
    /** Solve the problem assembled on level @p level (for initial guesses). */
    LevelVector solve_on_level(const unsigned int level, const LevelVector *start);
    /** Interpolate a rotated level-l vector to level l+1 (rotated). */
    LevelVector prolongate_rotated(const unsigned int to_level, const LevelVector &coarse) const;

    const Parameters::AllParameters &parameters;
    const Scene<dim> &               scene;
    const Discretization<dim> &      discretization;
    const LevelTransfer<dim> &       transfer;
    const ConditionalOStream &       pcout;
    /** See record(). */
    InitialGuessRecord guess_record;
  };
} // namespace FoslsContact

#endif
