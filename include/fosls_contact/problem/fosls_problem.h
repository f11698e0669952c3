#ifndef fosls_contact_problem_fosls_problem_h
#define fosls_contact_problem_fosls_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/output/output_directory.h>
#include <fosls_contact/output/postprocessor.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/problem/adaptive_steps.h>
#include <fosls_contact/problem/friction_law.h>
#include <fosls_contact/problem/initial_guess.h>
#include <fosls_contact/problem/load_steps.h>
#include <fosls_contact/problem/run_summary.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/scene.h>
#include <fosls_contact/solvers/monitor.h>
#include <fosls_contact/solvers/qp_solver.h>

#include <map>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace FoslsContact
{
  /**
   * The program, tutorial style: run() walks the data path
   *
   *   scene -> mesh and DoFs -> assembled functional -> constraints in
   *   normal-tangential coordinates -> solver -> output,
   *
   * one member function per box, each in its own TimerOutput section; an
   * adaptive run (Adaptivity) goes round from the assembly to the output
   * once per mesh, refining by the error indicators in between. It
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
    /**
     * Assemble the finest level's functional. Where only the multigrid
     * solve follows and the definiteness check runs on a coarser level,
     * the finest level's coupling pattern is freed during the compression
     * of A (ConstrainedQP::compress_matrices()), so that it and A's
     * compressed values are never held at once; otherwise setup_solver()
     * frees it, or (active set solvers, cross check) the run keeps it.
     */
    void assemble();
    /**
     * Refuse, before the mesh is refined, a run whose finest level does
     * not fit into the memory the processes may use (MemoryBudget), with
     * the number of levels that fits.
     */
    void check_memory() const;
    /**
     * Functional weights/C_compl = auto: take the weight
     * ProblemChecks::choose_compl_weight() chooses on the scene's mesh,
     * before the finest level is assembled (once: an adaptive run keeps
     * it, so that its steps minimize the same functional), and write it
     * into used_parameters.prm and summary.json.
     */
    void choose_weights();
    /**
     * Whether the run needs the finest level's coupling pattern after the
     * assembly (after the checks and the solver's set-up if @p after_setup):
     * the solvers that factorize the matrix and a definiteness check on
     * the finest level do, the multigrid solve does not.
     */
    bool needs_fine_coupling_pattern(const bool after_setup) const;
    /** The checks of the assembled problem (ProblemChecks). */
    void check_problem();
    void make_initial_guess();
    void setup_solver();
    /**
     * Solver/Cross check: solve the same problem with the active set
     * method from @p start and compare (cross_check_functional,
     * cross_check_solution).
     */
    void cross_check(const LevelVector &start);
    /**
     * The solve of the step: one problem, or with Coulomb friction the
     * fixed point of Tresca problems (slip bounds f times the pressure of
     * the last solution) to Friction/Fixed point tolerance.
     */
    void solve();
    /**
     * One run of the solver on qp from solution (and the cross check), its
     * tolerance relative to at least @p reference_correction
     * (Monitor::set_reference_correction()); @p tolerance, where > 0, in
     * place of Solver/Tolerance (the Coulomb fixed point's inexact Tresca
     * problems).
     */
    void run_solver(const double reference_correction = 0, const double tolerance = 0);
    /** The KKT residuals and the end of the solve, printed. */
    void report_solve();
    /**
     * With friction: the friction terms of the assembled qp, relative to
     * @p reference (the step's starting displacement, Cartesian with
     * ghost values; null: the undeformed body).
     */
    void set_friction(const LevelVector *reference);
    /**
     * With friction from the second load step on: the displacement
     * friction acts relative to, the previous step's solution (Cartesian,
     * ghosted, kept in @p storage); else nullptr (the undeformed body).
     */
    const LevelVector *step_reference(LevelVector &storage) const;
    /**
     * With friction: the stick and slip vertices and the normal and
     * tangential contact force (@p force split along the obstacle normal),
     * from the contact table @p rows with its friction columns (on the
     * first process), printed and in summary.json ("friction").
     */
    void add_friction_summary(const Tensor<1, dim> &                              force,
                              const std::vector<typename ContactRow<dim>::Values> &rows);
    /** The problem's friction terms, or null without friction (for the output). */
    const FrictionTerms *friction_terms() const
    {
      return qp.has_friction() ? &qp.friction : nullptr;
    }
    /**
     * The figures of this step's solution (summary.json's fields, printed
     * as well), its error indicators and its VTU files; a row of the step
     * table.
     */
    void output_step(OutputDirectory &output);
    /**
     * Refine by the error indicators and carry the solution over to the
     * new mesh as the next step's start; false if the DoF budget stops it.
     */
    bool refine();
    /**
     * Adaptivity/Reference refinements: refine every cell of the last
     * mesh that many times, carrying the solution (the reference solve's
     * start) and every step's solution (step_solutions) over.
     */
    void refine_for_reference();
    /**
     * Refine by @p criteria as @p marking says, carrying the solution
     * (made Cartesian and active first if @p from_solution, else the one
     * carried before) and step_solutions over; false if nothing was
     * refined (the DoF budget).
     */
    bool refine_carrying(const Vector<float> &         criteria,
                         const Parameters::Adaptivity &marking,
                         const bool                    from_solution);
    /** Whether the run asks for a reference and has not solved it yet. */
    bool reference_pending() const;
    /**
     * The start of a step after the first: the previous solution,
     * interpolated to the refined mesh, in the rotated basis (the solver
     * projects it onto the contact constraints).
     */
    void start_from_carried();
    /**
     * The start of a load step after the first: the previous step's
     * solution (carried) plus the change of Solver/Initial guess between
     * the two steps' data (Cartesian), in the rotated basis. The change
     * carries the new Dirichlet values and the coarse shape of the new
     * solution into the start, where the previous solution alone would
     * meet them only at the boundary (a layer of one cell the solver has
     * to smooth out); with Initial guess = zero it is the previous solution.
     * So it is on the mesh of an adaptive first step: Solver/Initial guess
     * solves on the uniform levels, whose transfer ends below that mesh.
     */
    void start_load_step();
    /** Whether the run follows a load path (Data/Load steps). */
    bool load_path() const { return !parameters.data.load_steps.empty(); }
    /**
     * The next step of the load path: the scene's data with that step's
     * constants, the levels' bounds and fixed values set up again on the
     * same mesh, and this step's solution (Cartesian) carried as its start.
     */
    void next_load_step();
    /**
     * The row of this step of the load path (load_steps), and its line;
     * @p rows the contact table (with contact; on the first process).
     */
    void add_load_step(const std::map<types::boundary_id, Tensor<1, dim>> &forces,
                       const Tensor<1, dim> &                              force,
                       const FunctionalValue &                             J,
                       const std::vector<typename ContactRow<dim>::Values> &rows);
    /** The files of the whole run, published with the steps' VTU files. */
    void finish(OutputDirectory &output);
    /**
     * After a SIGTERM or SIGINT (Interruption): publish the adaptive steps
     * finished so far, with the files of the last of them, and throw
     * InterruptedRun; without a finished step only throw.
     */
    [[noreturn]] void stop_interrupted(OutputDirectory &output);
    /** Append the resident memory after @p phase. Collective. */
    void record_memory(const std::string &phase);

    /**
     * The scene's parameters; with Functional weights/C_compl = auto, its
     * weight is the one choose_weights() takes.
     */
    Parameters::AllParameters parameters;
    /** used_parameters.prm (with the C_compl taken where it was auto). */
    std::string               used_parameters;
    ConditionalOStream              pcout;
    mutable TimerOutput             timer;

    Scene<dim>                           scene;
    std::unique_ptr<Discretization<dim>> discretization;
    std::unique_ptr<LevelTransfer<dim>>  transfer;
    ConstrainedQP                        qp;
    LevelVector                          solution;
    std::unique_ptr<QPSolver>            solver;
    std::unique_ptr<Monitor>             monitor;
    std::unique_ptr<ErrorIndicators<dim>> indicators;
    /** summary.json's fields, of the last step */
    std::map<std::string, std::string>   summary;
    AdaptiveSteps                        steps;
    /**
     * A load path: the initial guess (Solver/Initial guess) of the last
     * step's data, Cartesian, for start_load_step().
     */
    LevelVector                          load_step_guess;
    /**
     * With friction, C_compl = auto below this fraction of its cap prints
     * a warning: friction takes the limit on the square (lambda = mu) from
     * 0.30 to 0.22, on the graded half disc with lambda = inf from 0.53 to
     * below 1e-4 (tests/solver/friction).
     */
    static constexpr double friction_weak_compl = 1e-2;
    /** With friction: the law and the slip bounds of the friction faces. */
    std::unique_ptr<FrictionLaw<dim>>    friction_law;
    std::vector<double>                  slip_bounds;
    /** Coulomb: the Tresca problems of the step's fixed point. */
    unsigned int                         fixed_point_iterations = 0;
    /**
     * The corrections' reduction over the step's Tresca problems (one
     * without friction): the sum of Monitor::measured_reduction()'s
     * logarithms and iterations, for the step's rate per iteration.
     */
    std::pair<double, unsigned int>      step_reduction;
    /**
     * The iterations and linear cycles of the step's last Tresca problem
     * (one run of the solver, or two where the Coulomb fixed point
     * solves the accepted problem on to Solver/Tolerance): load_steps.csv's.
     */
    std::pair<unsigned int, unsigned int> problem_work;
    /** The rows of a load path (Data/Load steps), one per step. */
    LoadSteps<dim>                       load_steps;
    /**
     * The solve of the run: the step of the adaptive loop (0: the first,
     * uniform mesh), then of the load path; the time of its VTU files in
     * solution.pvd.
     */
    unsigned int                         step = 0;
    /**
     * The step of the load path (Data/Load steps; 0 without one). Its
     * first step runs the adaptive loop, the later ones are solved on the
     * loop's last mesh.
     */
    unsigned int                         load_step = 0;
    /** Where the solve of a step starts. */
    enum class Start
    {
      /** Solver/Initial guess: the run's first solve */
      first,
      /** the last solution on the refined mesh (start_from_carried()) */
      refined,
      /** the next load step (start_load_step()) */
      load_step
    };
    Start                                start = Start::first;
    /**
     * The rows of steps that belong to the adaptive loop: all, or along a
     * load path those of its first step (each later step adds one row to
     * both tables).
     */
    unsigned int adaptive_rows() const
    {
      return load_path() ? steps.size() + 1 - load_steps.size() : steps.size();
    }
    /** The last solution, Cartesian, carried over to the refined mesh. */
    LevelVector                          carried;
    /**
     * Adaptivity/Reference refinements: every step's solution (Cartesian,
     * scene units, as solution_in_scene_units()), carried over to every
     * refined mesh, and whether the last solve was the reference's.
     */
    std::vector<LevelVector>             step_solutions;
    bool                                 reference_solved = false;
    /**
     * Whether the memory available (MemoryBudget), rather than
     * Adaptivity/Max DoFs, bounded the last refinement.
     */
    bool memory_bounds_refinement = false;
    /** Why the adaptive loop stopped. */
    std::string                          adaptive_stop;
    /**
     * An adaptive run's last finished step (output_step()): its files
     * that finish() writes from the current solution, kept for
     * stop_interrupted(), which publishes them when a signal arrives while
     * the next step is under way.
     */
    struct FinishedStep
    {
      std::string                        contact_table, convergence;
      std::map<std::string, std::string> summary;
    };
    std::optional<FinishedStep>          finished;
    /**
     * C_compl = auto: the largest definite C_compl on the level of the
     * definiteness check (NaN: not computed, or C_compl given).
     */
    double compl_limit = std::numeric_limits<double>::quiet_NaN();
    /**
     * AdaptiveSteps::singular_stress()'s text once an adaptive run has
     * found a singular stress ("" before).
     */
    std::string singular_stress;
    /** The uniform levels the definiteness check passed (ProblemChecks). */
    std::set<unsigned int>               definite_levels;
    double                               time_setup = 0, time_solve = 0;
    std::vector<PhaseMemory>             phase_memory;
    /** What this process sent point to point during the solve. */
    CommunicationCounter                 solve_communication;
    /**
     * Solver/Cross check: J's relative difference to the active set
     * method's solution of the same problem, and the largest difference
     * of the two solutions' DoF values relative to the largest of that
     * solution's (the dimensionless DoFs; NaN without the check).
     */
    double cross_check_functional = std::numeric_limits<double>::quiet_NaN();
    double cross_check_solution   = std::numeric_limits<double>::quiet_NaN();
    /** The wall time of the cross check's solve. */
    double time_cross_check = 0;
    /**
     * The initial guess's nested iteration: its work on the coarser levels
     * and the rate floor of the finest level's stop (InitialGuess::record();
     * empty for the other starts).
     */
    InitialGuessRecord guess_record;
  };
} // namespace FoslsContact

#endif
