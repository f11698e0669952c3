#ifndef fosls_contact_problem_run_summary_h
#define fosls_contact_problem_run_summary_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/output/postprocessor.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/scene.h>
#include <fosls_contact/solvers/monitor.h>
#include <fosls_contact/solvers/qp_solver.h>

#include <map>
#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * Resident memory (MB, all processes) after a phase of FoslsProblem::run():
   * all of it, its peak so far, and the part that is file-backed (the pages
   * of the program and its shared libraries, which the kernel can drop and
   * reread; what the run allocates is the rest).
   */
  struct PhaseMemory
  {
    std::string phase;
    double      rss_mb;
    double      peak_rss_mb;
    double      rss_file_mb;
  };


  /**
   * The entries of summary.json, the record of a run that the tests and
   * bench/ scripts read: what the run cost, how the solver did, the
   * solution's figures in the scene's units, the Hertz comparison and the
   * errors against an exact solution. Each figure is computed from the
   * finished run's objects, so they are gathered here rather than in the
   * driver that made them.
   */
  template <int dim>
  class RunSummary
  {
  public:
    /** summary.json's entries by name, each JSON text (Postprocessor::write()). */
    using Summary = std::map<std::string, std::string>;

    RunSummary(const Parameters::AllParameters &parameters,
               const Scene<dim> &               scene,
               const Discretization<dim> &      discretization,
               const ConstrainedQP &            qp,
               const LevelVector &              solution,
               const QPSolver &                 solver,
               const Monitor &                  monitor,
               const ConditionalOStream &       pcout);

    /**
     * What the run cost: times, peak memory, communication (collective,
     * first in the output so that the peak memory is the solve's).
     */
    Summary cost(const TimerOutput &              timer,
                 const double                     time_setup,
                 const double                     time_solve,
                 const std::vector<PhaseMemory> & phase_memory,
                 const CommunicationCounter &     solve_communication) const;
    /** The problem's size and how the solver did (iterations, rates, statistics). */
    void add_solver(Summary &summary) const;
    /**
     * Where the memory goes: `memory_mb`, the megabytes of the program's
     * structures (summed over the processes) by structure: the mesh and
     * DoF handler, the level data, the uniform levels' prolongations
     * (@p transfer_bytes), the assembled problem and the solver's own
     * (SolverStatistics::Multilevel::memory); `memory_mb_by_level`, the
     * same without the mesh and DoF handler by level of the multigrid
     * hierarchy (entry l of each list: level l), whose sums are
     * `memory_mb`'s. Collective.
     */
    void add_memory(Summary &summary, const LevelBytes &transfer_bytes) const;
    /**
     * The round-off of J against J. A note if @p J (of the assembled
     * quadratic form, in the scene's units) and the sum of its cellwise
     * parts in @p indicators differ by more than 1e-3 relative (@p J_start:
     * J of the solve's start; a J at its round-off is no news). And
     * `functional_round_off` in @p summary, the last iterate's
     * IterateMeasures::functional_round_off over J: where it passes
     * #round_off_warning, the solvers cannot tell the solution from its
     * neighbours to the digits asked (doc/method.md, "Conditioning"),
     * which a warning line and `round_off_limited` with its cause
     * (Conditioning) say.
     */
    void add_round_off(Summary &                   summary,
                       const double                J,
                       const double                J_start,
                       const ErrorIndicators<dim> &indicators) const;
    /** The round-off of J, relative, from which a run is round-off limited. */
    static constexpr double round_off_warning = 1e-2;
    /**
     * The solution's figures in the scene's units: J and its parts, the
     * contact force, the error indicators, the largest displacement and
     * stress (@p maxima: Postprocessor::field_maxima()); returns J.
     */
    FunctionalValue add_solution(Summary &                   summary,
                                 const Postprocessor<dim> &  post,
                                 const LevelVector &         cartesian,
                                 const Tensor<1, dim> &      force,
                                 const ErrorIndicators<dim> &indicators,
                                 const FieldMaxima &         maxima) const;
    /**
     * The error estimate in the user's terms: sqrt(J) of the
     * dimensionless problem over the H1 x H(div) norm of the solution
     * there (ErrorNorms::scaled()), the relative error within the
     * constants of the functional's norm equivalence. Printed and written
     * to summary.json (relative_error_estimate); returns it. Collective.
     */
    double add_error_estimate(Summary &                   summary,
                              const Postprocessor<dim> &  post,
                              const LevelVector &         cartesian,
                              const ErrorIndicators<dim> &indicators) const;
    /**
     * The answers in an engineer's terms, on the screen with the units of
     * Scaling/Unit names and in summary.json: the contact force @p force
     * (the line "Contact force = ..."), @p forces, the resultant of sigma n on every
     * boundary id (Postprocessor::boundary_forces(): the force exerted on the
     * body there, a Dirichlet id's reaction) and their sum, the equilibrium
     * check; for a scene with contact the contact zone (ContactZone: width or
     * area, mean and peak pressure). Collective.
     */
    void add_forces(Summary &                                           summary,
                    const std::map<types::boundary_id, Tensor<1, dim>> &forces,
                    const Tensor<1, dim> &                              force) const;
    /**
     * The comparison with Hertz's contact pressure, for a scene that
     * declares one, on the contact table @p rows (ContactTable::rows(),
     * with the friction columns for a scene with friction); for a
     * cylinder in 2D with Coulomb friction also Cattaneo and Mindlin's
     * stick zone and tangential traction (CattaneoMindlin). Returns the
     * relative errors of the pressure: l2 at the contact vertices, and L2
     * on the contact boundary.
     */
    std::pair<double, double>
    add_hertz_comparison(Summary &                                            summary,
                         const Tensor<1, dim> &                               force,
                         const std::vector<typename ContactRow<dim>::Values> &rows) const;
    /** The errors against the scene's exact solution; refuses non-finite ones. */
    ErrorNorms add_errors(Summary &summary, const Postprocessor<dim> &post, const LevelVector &cartesian) const;

  private:
    const Parameters::AllParameters &parameters;
    const Scene<dim> &               scene;
    const Discretization<dim> &      discretization;
    const ConstrainedQP &            qp;
    const LevelVector &              solution;
    const QPSolver &                 solver;
    const Monitor &                  monitor;
    const ConditionalOStream &       pcout;
  };
} // namespace FoslsContact

#endif
