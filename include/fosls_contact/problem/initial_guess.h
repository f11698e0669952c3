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

    /**
     * The patch sweeps of the last compute()'s solves on coarser levels
     * (nested iteration), in sweeps over the finest level: the work the
     * guess adds to the solve's (SolverStatistics::Multilevel::work_units()).
     */
    double work_units() const { return work; }

    /**
     * The largest rate that the last compute()'s solves on coarser levels
     * (nested iteration) measured in their linear phase (Monitor::linear_rate()),
     * 0 for the other guesses: the finest level's solve, which starts next
     * to its solution, estimates its algebraic error with at least this
     * rate (Monitor::set_rate_floor()).
     */
    double measured_rate() const { return rate; }

    /** What one coarser level's solve of a nested iteration did. */
    struct LevelSolve
    {
      unsigned int level;
      types::global_dof_index dofs;
      unsigned int iterations;
      unsigned int cycles;
      /** Monitor::stop_reason() */
      std::string stop_reason;
      /** Monitor::linear_rate() */
      double linear_rate;
      /** J's increases (Monitor::energy_increases(); 0: J monotone) */
      unsigned int energy_increases;
      bool converged;
    };
    /**
     * The last compute()'s solves on levels 1 .. finest - 1 (nested
     * iteration; empty for the other guesses), for summary.json's
     * `nested_iteration`.
     */
    const std::vector<LevelSolve> &level_solves() const { return solves; }

    /** The JSON array of level_solves(). */
    std::string level_solves_json() const;

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
    /** The sweeps of the coarser levels' solves times their levels' DoFs. */
    double work = 0;
    /** See measured_rate(). */
    double rate = 0;
    /** See level_solves(). */
    std::vector<LevelSolve> solves;
  };
} // namespace FoslsContact

#endif
