#ifndef fosls_contact_fosls_problem_h
#define fosls_contact_fosls_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/output/monitor.h>
#include <fosls_contact/output/output_directory.h>
#include <fosls_contact/output/postprocessor.h>
#include <fosls_contact/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/scene.h>
#include <fosls_contact/solvers/qp_solver.h>

#include <map>
#include <memory>
#include <string>

namespace FoslsContact
{
  /**
   * The program, tutorial style: run() walks the data path
   *
   *   scene -> mesh and DoFs -> assembled functional -> constraints in
   *   normal-tangential coordinates -> solver -> output,
   *
   * one member function per box, each in its own TimerOutput section. It
   * runs on all processes of MPI_COMM_WORLD (started by mpirun) or on one;
   * the screen output comes from the first.
   */
  template <int dim>
  class FoslsProblem
  {
  public:
    FoslsProblem(const Parameters::AllParameters &parameters,
                 const std::string &              used_parameters);

    /**
     * Run the program: check and lock the output directory, then the data
     * path; the output files are published when it ends. Returns "" if the
     * solver converged, else why not, in a few words for the one line the
     * program ends with (the files are written either way).
     */
    std::string run();

  private:
    void setup();
    void assemble();
    /** Refuse data (Dirichlet values, traction, gap, body force) that are not finite. */
    void check_data();
    /**
     * Refuse boundary conditions that leave a rigid motion free: the
     * functional is then only semidefinite, the coarsest level singular
     * and the iterates drift along the motion.
     */
    void check_rigid_motions();
    void check_definiteness();
    void make_initial_guess();
    void setup_solver();
    void solve();
    void output_results(OutputDirectory &output);

    /** summary.json's entries by name, each JSON text (Postprocessor::write()). */
    using Summary = std::map<std::string, std::string>;
    /**
     * What the run cost: times, peak memory, communication (collective,
     * first in output_results() so that the peak memory is the solve's).
     */
    Summary cost_summary() const;
    /** The problem's size and how the solver did (iterations, rates, statistics). */
    void add_solver_summary(Summary &summary) const;
    /**
     * The solution's figures in the scene's units: J and its parts, the
     * contact force, the error indicators, the largest displacement and
     * stress; returns J.
     */
    FunctionalValue add_solution_summary(Summary &                   summary,
                                         const Postprocessor<dim> &  post,
                                         const LevelVector &         cartesian,
                                         const Tensor<1, dim> &      force,
                                         const ErrorIndicators<dim> &indicators) const;
    /** The comparison with Hertz's contact pressure, for a scene that declares one. */
    void add_hertz_comparison(Summary &                 summary,
                              const Postprocessor<dim> &post,
                              const Tensor<1, dim> &    force) const;
    /** The errors against the scene's exact solution; refuses non-finite ones. */
    void add_errors(Summary &summary, const Postprocessor<dim> &post, const LevelVector &cartesian) const;

    /**
     * A solver for @p level_qp, the problem assembled on level @p level.
     */
    std::unique_ptr<QPSolver> make_solver(const ConstrainedQP &level_qp,
                                          const unsigned int   level) const;
    /** Solve the problem assembled on level @p level (for initial guesses). */
    LevelVector solve_on_level(const unsigned int level, const LevelVector *start) const;
    /** Interpolate a rotated level-l vector to level l+1 (rotated). */
    LevelVector prolongate_rotated(const unsigned int to_level, const LevelVector &coarse) const;

    const Parameters::AllParameters parameters;
    const std::string               used_parameters;
    ConditionalOStream              pcout;
    mutable TimerOutput             timer;

    Scene<dim>                           scene;
    std::unique_ptr<Discretization<dim>> discretization;
    std::unique_ptr<LevelTransfer<dim>>  transfer;
    ConstrainedQP                        qp;
    LevelVector                          solution;
    std::unique_ptr<QPSolver>            solver;
    std::unique_ptr<Monitor>             monitor;
    double                               time_setup = 0, time_solve = 0;
    /** Resident memory (MB, all processes) after a phase of run(). */
    struct PhaseMemory
    {
      std::string phase;
      double      rss_mb;
      double      peak_rss_mb;
    };
    std::vector<PhaseMemory> phase_memory;
    /** Append the resident memory after @p phase. Collective. */
    void record_memory(const std::string &phase);
    /** What this process sent point to point during the solve. */
    CommunicationCounter                 solve_communication;
  };
} // namespace FoslsContact

#endif
