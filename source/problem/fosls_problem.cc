#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/base/collective_error.h>
#include <fosls_contact/base/interruption.h>
#include <fosls_contact/base/json.h>
#include <fosls_contact/output/contact_zone.h>
#include <fosls_contact/output/postprocessor.h>
#include <fosls_contact/problem/fosls_problem.h>
#include <fosls_contact/problem/initial_guess.h>
#include <fosls_contact/problem/memory_budget.h>
#include <fosls_contact/problem/problem_checks.h>
#include <fosls_contact/problem/solver_choice.h>
#include <fosls_contact/solvers/active_set_direct.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace FoslsContact
{
  template <int dim>
  FoslsProblem<dim>::FoslsProblem(const Parameters::AllParameters &parameters,
                                  const std::string &used_parameters)
    : parameters(parameters)
    , used_parameters(used_parameters)
    , pcout(std::cout,
            parameters.output.verbose &&
              Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , scene(parameters)
  {}


  template <int dim>
  void
  FoslsProblem<dim>::setup()
  {
    TimerOutput::Scope t(timer, "Setup: mesh, DoFs, levels");
    Timer              wall;
    check_memory();
    // adaptive refinement needs the whole mesh on every process
    // (Discretization explains why); a uniform mesh is partitioned
    using Distribution = typename Discretization<dim>::MeshDistribution;
    discretization     = std::make_unique<Discretization<dim>>(scene,
                                                          parameters.geometry.levels,
                                                          MPI_COMM_WORLD,
                                                          parameters.adaptivity.enabled() ?
                                                            Distribution::replicated :
                                                            Distribution::partitioned);
    transfer = std::make_unique<LevelTransfer<dim>>(*discretization);
    time_setup += wall.wall_time();

    const auto &   fine = discretization->level(discretization->finest_level());
    const MPI_Comm comm = discretization->get_communicator();
    pcout << "Scene: " << dim << "D, " << discretization->n_levels()
          << " levels, " << discretization->get_triangulation().n_global_active_cells()
          << " cells, " << fine.n_dofs << " DoFs on the finest level" << std::endl
          << "       coarse mesh h_max/h_min = " << std::fixed
          << std::setprecision(4) << discretization->coarse_mesh_ratio()
          << std::defaultfloat << std::endl;
    const unsigned int n_processes = Utilities::MPI::n_mpi_processes(comm);
    if (n_processes > 1)
      pcout << "       " << n_processes << " MPI processes, "
            << MultithreadInfo::n_threads() << " thread(s) each" << std::endl;
    const auto &m = parameters.material;
    pcout << "       material: mu = " << m.mu << ", lambda = " << m.lambda
          << " (E = " << m.youngs_modulus << ", nu = " << m.poisson_ratio
          << "); solved in units of L = " << scene.scaling().length
          << ", S = " << scene.scaling().stress << std::endl;
    if (scene.has_contact())
      {
        unsigned int n_vertices = 0, n_faces = 0;
        for (const auto &v : fine.contact_vertices)
          n_vertices += v.owned;
        for (const auto &f : fine.contact_faces)
          n_faces += f.owned;
        pcout << "       contact: " << Utilities::MPI::sum(n_vertices, comm)
              << " vertices, " << Utilities::MPI::sum(n_faces, comm) << " faces"
              << std::endl;
      }
    else
      pcout << "       no contact boundary: linear FOSLS problem" << std::endl;
  }


  template <int dim>
  void
  FoslsProblem<dim>::check_memory() const
  {
    // The DoFs of the finest level from the coarse mesh: every uniform
    // refinement multiplies the cells by 2^dim, and a mesh of N cells has
    // about N vertices and dim N faces, each with dim DoFs (Q1^dim x
    // RT0^dim): 6 N in 2D, 12 N in 3D, the boundary's surplus aside.
    Triangulation<dim> coarse;
    scene.make_coarse_mesh(coarse);
    const unsigned int levels = parameters.geometry.levels;
    const double       dofs   = dim * (1. + dim) * coarse.n_active_cells() *
                        std::pow(2., dim * (levels - 1.));
    const MemoryBudget budget(dim, parameters.adaptivity.enabled(), MPI_COMM_WORLD);
    // (the largest level count that fits, for the advice)
    unsigned int fitting = levels;
    while (fitting > 1 && dofs / std::pow(2., dim * (levels - fitting)) > budget.affordable_dofs())
      --fitting;
    budget.check(dofs,
                 "lower 'Geometry/Levels' (" + std::to_string(levels) + ")" +
                   (fitting < levels ? " to at most " + std::to_string(fitting) : std::string()) +
                   ", or run on more processes of more nodes");
  }


  template <int dim>
  void
  FoslsProblem<dim>::assemble()
  {
    TimerOutput::Scope t(timer, "Assembly");
    Timer              wall;
    const unsigned int L = discretization->finest_level();
    qp.reinit(discretization->level(L));
    std::function<void()> release;
    if (!needs_fine_coupling_pattern(false))
      release = [this, L]() { discretization->release_coupling_pattern(L); };
    LevelVector        reference;
    const LevelVector *friction_reference = step_reference(reference);
    FoslsAssembler<dim>(*discretization, parameters.weights, friction_reference)
      .assemble(L, qp, release);
    if (scene.has_friction())
      set_friction(friction_reference);
    time_setup += wall.wall_time();
  }


  template <int dim>
  const LevelVector *
  FoslsProblem<dim>::step_reference(LevelVector &storage) const
  {
    // (friction acts on the displacement relative to the step's start:
    // the previous load step's solution, or the undeformed body)
    if (!scene.has_friction() || load_step == 0)
      return nullptr;
    storage = carried;
    update_ghosts(storage);
    return &storage;
  }


  template <int dim>
  void
  FoslsProblem<dim>::set_friction(const LevelVector *reference)
  {
    const unsigned int L = discretization->finest_level();
    friction_law = std::make_unique<FrictionLaw<dim>>(scene,
                                                      discretization->level(L),
                                                      parameters.weights.c_compl);
    LevelVector p(qp.partitioner);
    if (reference != nullptr)
      {
        p.copy_locally_owned_data_from(*reference);
        update_ghosts(p);
        discretization->rotate_to_normal_tangential(L, p);
      }
    update_ghosts(p);
    friction_law->set_reference(qp, p);
    // (Coulomb: the pressure the step starts from, none on the
    // undeformed body, whose first Tresca problem is frictionless)
    slip_bounds = friction_law->slip_bounds(p);
    friction_law->set_bounds(qp, slip_bounds);
  }


  template <int dim>
  void
  FoslsProblem<dim>::choose_weights()
  {
    auto &w = parameters.weights;
    if (w.c_compl_auto)
      {
        const ProblemChecks<dim> checks(parameters, scene, *discretization, qp, pcout);
        const auto chosen = checks.choose_compl_weight(timer, definite_levels);
        w.c_compl         = chosen.value;
        // used_parameters.prm runs the same functional again
        std::ostringstream value;
        value << std::setprecision(17) << w.c_compl << "  # auto";
        if (std::isfinite(chosen.limit))
          value << ": the largest definite value " << std::setprecision(4) << chosen.limit
                << " on level " << chosen.level + 1;
        // (the one line 'set C_compl = auto' of ParameterHandler's output)
        std::istringstream lines(used_parameters);
        std::string        replaced;
        for (std::string line; std::getline(lines, line);)
          {
            const auto set = line.find("set C_compl");
            const auto eq  = line.find('=', set);
            if (set != std::string::npos && eq != std::string::npos &&
                Utilities::trim(line.substr(eq + 1)) == "auto")
              line = line.substr(0, eq + 1) + " " + value.str();
            replaced += line + "\n";
          }
        used_parameters = replaced;
        compl_limit = chosen.limit;
        // With friction the tangential tractions are free, and a stress
        // that costs nothing without them (the pressure sigma = p I of an
        // incompressible body, whose traction p n has a part along a
        // curved contact boundary) can leave the quadratic form close to
        // singular: the weight that keeps it definite is then too small
        // to enforce complementarity (doc/method.md section 10)
        if (scene.has_friction() &&
            w.c_compl < friction_weak_compl * Parameters::Weights::auto_compl_cap)
          pcout << "Warning: with friction C_compl = auto takes " << std::setprecision(3)
                << w.c_compl << ", " << Parameters::Weights::auto_compl_cap / w.c_compl
                << " times below its cap: the functional is close to indefinite (an "
                   "incompressible body on a curved contact boundary?), complementarity "
                   "is weakly enforced, and the contact pressure may be far off"
                << std::defaultfloat << std::endl;
      }
  }


  template <int dim>
  bool
  FoslsProblem<dim>::needs_fine_coupling_pattern(const bool after_setup) const
  {
    const auto &solver = parameters.solver;
    // (active set and projected Gauss-Seidel factorize or gather on it, a
    // one-level multigrid solves its only level directly, and the cross
    // check runs the active set method)
    if (solver.type != Parameters::Solver::Type::monotone_multigrid || solver.cross_check ||
        discretization->finest_level() == 0)
      return true;
    // (the definiteness check may factorize the finest level)
    const bool checked_here = ProblemChecks<dim>::definiteness_level(*discretization, solver) ==
                              static_cast<int>(discretization->finest_level());
    return checked_here && !after_setup;
  }


  template <int dim>
  void
  FoslsProblem<dim>::check_problem()
  {
    const ProblemChecks<dim> checks(parameters, scene, *discretization, qp, pcout);
    checks.check_data();
    checks.check_rigid_motions();
    time_setup += checks.check_definiteness(timer, &definite_levels);
  }


  template <int dim>
  void
  FoslsProblem<dim>::make_initial_guess()
  {
    TimerOutput::Scope t(timer, "Initial guess");
    InitialGuess<dim> guess(parameters, scene, *discretization, *transfer, pcout);
    guess.compute(qp, solution);
    guess_record = guess.record();
    if (load_path())
      {
        load_step_guess = solution;
        discretization->rotate_to_cartesian(discretization->finest_level(), load_step_guess);
      }
  }


  template <int dim>
  void
  FoslsProblem<dim>::start_load_step()
  {
    TimerOutput::Scope t(timer, "Initial guess");
    const unsigned int L = discretization->finest_level();
    solution.reinit(qp.partitioner);
    solution.copy_locally_owned_data_from(carried);
    // (Solver/Initial guess reaches the uniform levels only: an adaptive
    // mesh starts from the previous solution alone)
    const bool adaptive_mesh = discretization->level(L).active_mesh;
    if (!adaptive_mesh)
      {
        LevelVector guess;
        // (quietly: the guess's own violation is not the start's)
        const ConditionalOStream quiet(std::cout, false);
        InitialGuess<dim> initial_guess(parameters, scene, *discretization, *transfer, quiet);
        initial_guess.compute(qp, guess);
        guess_record = initial_guess.record();
        discretization->rotate_to_cartesian(L, guess);
        LevelVector change(qp.partitioner), previous(qp.partitioner);
        change.copy_locally_owned_data_from(guess);
        previous.copy_locally_owned_data_from(load_step_guess);
        change -= previous;
        solution += change;
        load_step_guess = guess;
      }
    else
      guess_record = {};
    update_ghosts(solution);
    discretization->rotate_to_normal_tangential(L, solution);
    pcout << "Initial guess: the previous load step's solution"
          << (adaptive_mesh ? "" : " plus the change of the initial guess")
          << "; it violates the constraints (Dirichlet values, contact bounds) by "
          << std::scientific << std::setprecision(3)
          << qp.max_violation(solution) * scene.scaling().length << std::defaultfloat
          << " (projected onto them)" << std::endl;
  }


  template <int dim>
  void
  FoslsProblem<dim>::setup_solver()
  {
    // The solver's set-up (for multigrid: the rotated prolongations, the
    // vertex patches and the sparsity patterns of the Galerkin products)
    // depends on the mesh and on the pattern of the assembled matrix only
    // (so it comes after assemble()): set-up time, not solve time.
    TimerOutput::Scope t(timer, "Setup: solver");
    Timer              wall;
    const std::string  warning =
      SolverChoice<dim>::active_set_warning(parameters.solver.type, qp.size());
    if (!warning.empty())
      pcout << warning << std::endl;
    solver = SolverChoice<dim>::make(
      parameters.solver, *discretization, *transfer, qp, discretization->finest_level());
    // (released during the assembly where the checks did not need it)
    if (qp.coupling_sparsity && !needs_fine_coupling_pattern(true))
      {
        discretization->release_coupling_pattern(discretization->finest_level());
        qp.coupling_sparsity = nullptr;
      }
    time_setup += wall.wall_time();
  }


  template <int dim>
  void
  FoslsProblem<dim>::solve()
  {
    // (an adaptive step starts from the last mesh's solution: the Coulomb
    // fixed point starts from its pressure, not from the frictionless
    // problem of the undeformed body, which the interpolated solution is far
    // from: on the square the multigrid took 200 iterations for that
    // problem, against 2 to 4 for the others)
    if (scene.friction_law() == Parameters::Friction::Law::coulomb && start == Start::refined)
      {
        update_ghosts(solution);
        slip_bounds = friction_law->slip_bounds(solution);
        friction_law->set_bounds(qp, slip_bounds);
      }
    step_reduction = {0., 0u};
    problem_work   = {0u, 0u};
    // With Friction/Tresca accuracy > 0 an inexact fixed point: a Tresca
    // problem whose bounds are still the fixed point's change away from
    // their limit is solved to that factor times the change (the first
    // one's change taken as 1), the one whose bounds the fixed point
    // accepts on to Solver/Tolerance (doc/method.md, section 7.7,
    // "Inexact Tresca problems"); the monotone multigrid's only: the active
    // set method finds the active set and then solves exactly, so a looser
    // tolerance saves it no step, and every restart costs steps.
    const bool   coulomb = scene.friction_law() == Parameters::Friction::Law::coulomb;
    const double full_tolerance = parameters.solver.tolerance;
    const bool   inexact =
      coulomb && parameters.solver.type == Parameters::Solver::Type::monotone_multigrid &&
      parameters.solver.stopping == Parameters::Solver::Stopping::tolerance;
    double tolerance =
      inexact ? std::max(full_tolerance, parameters.friction.tresca_accuracy) : full_tolerance;
    run_solver(0, tolerance);
    fixed_point_iterations = 1;
    // (the later Tresca problems' tolerance relative to the first one's
    // first correction: Monitor::set_reference_correction())
    const double first_correction = monitor->first_correction();
    if (coulomb)
      for (;;)
        {
          // (a SIGTERM or SIGINT ends the fixed point with the Tresca
          // problem it stopped: the run then keeps what it finished, and the
          // fixed point would otherwise go on through its remaining
          // problems, each stopped after one iteration)
          if (monitor->stop_reason() == "interrupted")
            break;
          update_ghosts(solution);
          const std::vector<double> s      = friction_law->slip_bounds(solution);
          const double              change = friction_law->relative_change(slip_bounds, s);
          pcout << "Coulomb fixed point: Tresca problem " << fixed_point_iterations
                << ", the slip bounds of its solution differ by " << std::scientific
                << std::setprecision(3) << change << std::defaultfloat
                << " (relative to the largest)" << std::endl;
          if (change <= parameters.friction.fixed_point_tolerance)
            {
              if (tolerance == full_tolerance)
                break;
              // (then its bounds are compared again)
              tolerance = full_tolerance;
              pcout << "Coulomb fixed point: Tresca problem " << fixed_point_iterations
                    << " solved on to Solver/Tolerance" << std::endl;
              run_solver(first_correction, tolerance);
              continue;
            }
          if (fixed_point_iterations == parameters.friction.fixed_point_iterations)
            {
              std::ostringstream why;
              why << "the Coulomb fixed point still changes the slip bounds by "
                  << std::setprecision(3) << change << " (relative) after 'Friction/Fixed "
                  << "point iterations' = " << fixed_point_iterations << " Tresca problems";
              monitor->set_not_converged(why.str());
              break;
            }
          slip_bounds = s;
          friction_law->set_bounds(qp, slip_bounds);
          ++fixed_point_iterations;
          problem_work = {0u, 0u};
          if (inexact)
            tolerance = std::max(full_tolerance, parameters.friction.tresca_accuracy * change);
          run_solver(first_correction, tolerance);
        }
    report_solve();
  }


  template <int dim>
  void
  FoslsProblem<dim>::run_solver(const double reference_correction, const double tolerance)
  {
    TimerOutput::Scope t(timer, "Solve");
    Timer              wall;
    Parameters::Solver solver_parameters = parameters.solver;
    if (tolerance > 0)
      solver_parameters.tolerance = tolerance;
    monitor = std::make_unique<Monitor>(qp,
                                        solver_parameters,
                                        pcout,
                                        SolverChoice<dim>::name(parameters.solver.type));
    monitor->set_functional_unit(scene.scaling().functional(dim));
    monitor->set_reference_correction(reference_correction);
    monitor->set_rate_floor(guess_record.rate);
    const CommunicationCounter before = communication();
    const LevelVector          start(solution);
    solver->solve(qp, solution, *monitor);
    time_solve += wall.wall_time();
    const auto [log_reduction, iterations] = monitor->measured_reduction();
    step_reduction.first += log_reduction;
    step_reduction.second += iterations;
    problem_work.first += monitor->iterations();
    problem_work.second += monitor->cycles();
    solve_communication = {communication().exchanges - before.exchanges,
                           communication().values - before.values};
    if (parameters.solver.cross_check)
      cross_check(start);
  }


  template <int dim>
  void
  FoslsProblem<dim>::report_solve()
  {
    const KKTResidual kkt = qp.kkt_residual(solution);
    pcout << "KKT residuals: stationarity " << std::scientific
          << std::setprecision(3) << kkt.stationarity << ", feasibility "
          << kkt.feasibility << ", complementarity " << kkt.complementarity
          << std::defaultfloat << std::endl;
    pcout << (monitor->converged() ? "Converged" : "NOT converged") << " after "
          << monitor->iterations() << " iterations"
          << (monitor->stopped_at_round_off() ?
                " (corrections at their round-off floor)" :
              monitor->stop_reason() == "discretization accuracy" ?
                " (Stopping criterion = discretization accuracy: the algebraic error estimate "
                "below Discretization fraction times sqrt(J))" :
                "");
    if (monitor->stop_reason() == "diverged")
      pcout << ": J increased";
    if (monitor->stop_reason() == "stalled")
      pcout << ": stalled at a rate of " << std::fixed << std::setprecision(4)
            << monitor->asymptotic_rate() << " per iteration, its error estimate "
            << std::scientific << std::setprecision(1) << monitor->stalled_error_ratio()
            << " times the target of "
            << (parameters.solver.stopping == Parameters::Solver::Stopping::tolerance ?
                  "Solver/Tolerance" :
                  "Solver/Discretization fraction")
            << std::defaultfloat
            << (parameters.solver.krylov_steps == 0 ?
                  "; the default solver (Solver/Krylov steps > 0) converges there" :
                  "; Solver/Type = active set solves the problem exactly");
    pcout << std::endl;
  }


  template <int dim>
  void
  FoslsProblem<dim>::cross_check(const LevelVector &start)
  {
    // the reference: the active set method from the same start, quietly;
    // its time is not solve time
    TimerOutput::Scope       t(timer, "Cross check");
    const ConditionalOStream quiet(std::cout, false);
    Monitor                  reference_monitor(qp, parameters.solver, quiet, "active set");
    LevelVector              reference(start);
    Timer                    wall;
    ActiveSetDirect().solve(qp, reference, reference_monitor);
    time_cross_check = wall.wall_time();
    const double J = qp.value(solution), J_reference = qp.value(reference);
    LevelVector  difference(solution);
    difference -= reference;
    cross_check_functional = std::abs(J - J_reference) / std::abs(J_reference);
    cross_check_solution   = difference.linfty_norm() / reference.linfty_norm();
    pcout << "Cross check (Solver/Cross check): the active set method's solution differs by "
          << std::scientific << std::setprecision(2) << cross_check_solution
          << " in the largest DoF value (relative), its J by " << cross_check_functional << " (relative)"
          << std::defaultfloat << std::endl;
  }


  template <int dim>
  void
  FoslsProblem<dim>::output_step(OutputDirectory &output)
  {
    TimerOutput::Scope    t(timer, "Output");
    const RunSummary<dim> run_summary(
      parameters, scene, *discretization, qp, solution, *solver, *monitor, pcout);
    summary = run_summary.cost(timer, time_setup, time_solve, phase_memory, solve_communication);
    const auto &w = parameters.weights;
    summary["functional_weights"] =
      "{\"C_eq\": " + json_number(w.c_eq) + ", \"C_const\": " + json_number(w.c_const) +
      ", \"C_compl\": " + json_number(w.c_compl) +
      ", \"C_compl_auto\": " + (w.c_compl_auto ? "true" : "false") +
      ", \"C_compl_limit\": " + json_number(compl_limit) + "}";
    Postprocessor<dim>   post(*discretization, parameters, friction_terms());
    const LevelVector    cartesian = post.solution_in_scene_units(solution);
    // (the resultant of sigma n on every boundary id, once per step)
    const auto           forces    = post.boundary_forces(cartesian);
    const Tensor<1, dim> force     = post.contact_force(forces);
    indicators = std::make_unique<ErrorIndicators<dim>>(*discretization, parameters.weights);
    {
      // (J's friction terms: those of the step's assembly and last Tresca problem)
      LevelVector                                  reference;
      const typename ErrorIndicators<dim>::Friction friction{qp, step_reference(reference)};
      indicators->compute(solution, scene.has_friction() ? &friction : nullptr);
    }
    run_summary.add_solver(summary);
    if (parameters.solver.initial_guess == Parameters::Solver::InitialGuess::nested_iteration)
      {
        summary["work_units_initial_guess"] = json_number(guess_record.work_units);
        summary["nested_iteration"]         = guess_record.level_solves_json();
      }
    run_summary.add_memory(summary, transfer->memory_consumption());
    if (parameters.solver.cross_check)
      summary["cross_check"] = "{\"functional\": " + json_number(cross_check_functional) +
                               ", \"solution\": " + json_number(cross_check_solution) + "}";
    const FieldMaxima     maxima = post.field_maxima(cartesian);
    const FunctionalValue J =
      run_summary.add_solution(summary, post, cartesian, force, *indicators, maxima);
    // (the contact table with its friction columns, gathered once for the
    // friction summary, the load step's row and the Hertz comparison)
    std::vector<typename ContactRow<dim>::Values> contact_rows;
    const bool hertz = parameters.hertz.shape != Parameters::HertzComparison::Shape::none;
    if (scene.has_contact() && (scene.has_friction() || load_path() || hertz))
      contact_rows = ContactTable<dim>(*discretization, friction_terms()).rows(solution);
    if (scene.has_friction())
      add_friction_summary(force, contact_rows);

    AdaptiveSteps::Step row;
    row.cells      = discretization->get_triangulation().n_global_active_cells();
    row.dofs       = qp.size();
    row.iterations = monitor->iterations();
    row.converged  = monitor->converged();
    row.cycles           = monitor->cycles();
    row.cross_check_functional = cross_check_functional;
    row.cross_check_solution   = cross_check_solution;
    row.time_cross_check_s     = time_cross_check;
    row.energy_increases = monitor->energy_increases();
    row.functional       = J.total;
    row.functional_dimensionless = J.total / scene.scaling().functional(dim);
    row.max_von_mises            = maxima.von_mises;
    row.von_mises_position       = maxima.von_mises_position;
    row.von_mises_cell_diameter  = maxima.von_mises_cell_diameter;
    row.functional_start = monitor->get_history().front().functional.total *
                           scene.scaling().functional(dim);
    for (unsigned int d = 0; d < dim; ++d)
      row.force.push_back(force[d]);
    row.time_solve_s = time_solve - steps.total_solve_time();
    if (hertz && scene.has_contact())
      std::tie(row.hertz_pressure_error, row.hertz_pressure_error_boundary) =
        run_summary.add_hertz_comparison(summary, force, contact_rows);
    if (scene.has_exact_solution())
      {
        const ErrorNorms e   = run_summary.add_errors(summary, post, cartesian);
        row.error_u_h1       = e.u_h1();
        row.error_sigma_hdiv = e.sigma_hdiv();
      }

    pcout << "Functional J = " << std::scientific << std::setprecision(6)
          << J.total << " (eq " << J.eq << ", const " << J.constitutive
          << ", compl " << J.complementarity << ")" << std::defaultfloat
          << std::endl;
    run_summary.add_round_off(summary, J.total, row.functional_start, *indicators);
    row.relative_error_estimate =
      run_summary.add_error_estimate(summary, post, cartesian, *indicators);
    run_summary.add_forces(summary, forces, force);
    if (load_path())
      add_load_step(forces, force, J, contact_rows);
    row.reference = reference_solved;
    if (parameters.adaptivity.reference_refinements > 0)
      {
        if (!reference_solved)
          step_solutions.push_back(cartesian);
        else
          {
            for (unsigned int s = 0; s < step_solutions.size(); ++s)
              {
                const ErrorNorms e = post.difference(cartesian, step_solutions[s]);
                steps.set_reference_errors(s,
                                           e.u_h1(),
                                           e.sigma_hdiv(),
                                           e.scaled(scene.scaling(), dim));
                pcout << "Step " << s << " against the reference: |u_ref - u_h|_H1 = "
                      << std::scientific << std::setprecision(4) << e.u_h1()
                      << ", |sigma_ref - sigma_h|_Hdiv = " << e.sigma_hdiv()
                      << ", efficiency index " << std::fixed << std::setprecision(3)
                      << steps.at(s).efficiency_index() << std::defaultfloat << std::endl;
              }
            step_solutions.clear();
          }
      }
    const std::string table = post.write_step(solution, *indicators, step, output);
    steps.add(row);
    // (said once, and kept in summary.json from the step it was found on)
    std::string singular;
    if (load_step == 0 && singular_stress.empty() &&
        steps.singular_stress(parameters.scaling.unit_names.stress, singular))
      {
        singular_stress = singular;
        pcout << "Warning: " << singular_stress << std::endl;
      }
    if (!singular_stress.empty())
      summary["singular_stress"] = "\"" + singular_stress + "\"";
    if (parameters.adaptivity.enabled() || load_path())
      finished = FinishedStep{table, monitor->csv(), summary};
  }


  template <int dim>
  void
  FoslsProblem<dim>::add_load_step(const std::map<types::boundary_id, Tensor<1, dim>> &forces,
                                   const Tensor<1, dim> &                              force,
                                   const FunctionalValue &                             J,
                                   const std::vector<typename ContactRow<dim>::Values> &rows)
  {
    typename LoadSteps<dim>::Step row;
    row.output_index = step;
    for (const auto &changes : parameters.data.load_steps)
      for (const auto &change : changes)
        row.constants[change.first] = scene.constant(change.first);
    row.iterations = problem_work.first;
    row.cycles     = problem_work.second;
    if (const auto multilevel = solver->statistics().multilevel)
      row.linear_rate = multilevel->linear_rate();
    if (step_reduction.second > 0)
      row.iteration_rate = std::exp(step_reduction.first / step_reduction.second);
    row.converged  = monitor->converged();
    row.functional = J.total;
    row.force      = force;
    for (const auto &[id, f] : forces)
      if (scene.is_dirichlet(id))
        row.reactions[id] = f;
    if (scene.has_contact())
      {
        // (gathered on the first process, which writes the table)
        const ContactZone<dim> zone(rows);
        row.friction = scene.has_friction();
        if (row.friction)
          std::tie(row.stick_vertices, row.slip_vertices) = LoadSteps<dim>::count_status(rows);
        row.contact_measure     = zone.measure();
        row.peak_pressure       = zone.peak_pressure();
        row.vertices_in_contact = zone.vertices_in_contact();
        const double L          = scene.scaling().length;
        LoadSteps<dim>::split_force(row, rows, [&](const Point<dim> &x) {
          return scene.obstacle_normal(x / L);
        });
      }
    load_steps.set(load_step, row);
  }


  template <int dim>
  void
  FoslsProblem<dim>::add_friction_summary(const Tensor<1, dim> &                              force,
                                         const std::vector<typename ContactRow<dim>::Values> &rows)
  {
    // (the rows are gathered on the first process, which prints and
    // writes summary.json)
    typename LoadSteps<dim>::Step step;
    step.force     = force;
    const double L = scene.scaling().length;
    LoadSteps<dim>::split_force(step, rows, [&](const Point<dim> &x) {
      return scene.obstacle_normal(x / L);
    });
    const auto [stick, slip] = LoadSteps<dim>::count_status(rows);
    const bool tresca        = scene.friction_law() == Parameters::Friction::Law::tresca;
    pcout << "Friction (" << (tresca ? "Tresca" : "Coulomb") << "): " << stick << " stick and "
          << slip << " slip vertices, normal force " << std::setprecision(8) << step.normal_force
          << ", tangential force " << step.tangential_force;
    if (!tresca)
      pcout << ", " << fixed_point_iterations << " Tresca problems";
    pcout << std::defaultfloat << std::endl;
    summary["friction"] = std::string("{\"law\": \"") + (tresca ? "Tresca" : "Coulomb") +
                          "\", \"stick_vertices\": " + std::to_string(stick) +
                          ", \"slip_vertices\": " + std::to_string(slip) +
                          ", \"normal_force\": " + json_number(step.normal_force) +
                          ", \"tangential_force\": " + json_number(step.tangential_force) +
                          ", \"fixed_point_iterations\": " +
                          std::to_string(fixed_point_iterations) + "}";
  }


  template <int dim>
  void
  FoslsProblem<dim>::next_load_step()
  {
    TimerOutput::Scope t(timer, "Load step");
    Timer              wall;
    const unsigned int L = discretization->finest_level();
    // (in Cartesian coordinates: the rotations follow the obstacle normal,
    // which may change with the step's constants)
    carried = solution;
    discretization->rotate_to_cartesian(L, carried);
    scene.set_load_step(parameters, ++load_step);
    CollectiveError::run(discretization->get_communicator(),
                         [&]() { discretization->update_data(); });
    // (the solver's hierarchy holds the levels' rotations and bounds)
    solver.reset();
    transfer = std::make_unique<LevelTransfer<dim>>(*discretization);
    time_setup += wall.wall_time();
  }


  template <int dim>
  bool
  FoslsProblem<dim>::refine()
  {
    Vector<float> criteria(discretization->get_triangulation().n_active_cells());
    for (const auto &cell : discretization->get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        criteria[cell->active_cell_index()] = indicators->squared(cell->active_cell_index());
    // no step beyond what fits into memory (MemoryBudget), nor beyond
    // Adaptivity/Max DoFs
    Parameters::Adaptivity marking = parameters.adaptivity;
    const types::global_dof_index affordable =
      MemoryBudget(dim, true, MPI_COMM_WORLD).affordable_dofs();
    memory_bounds_refinement = marking.max_dofs == 0 || affordable < marking.max_dofs;
    if (memory_bounds_refinement)
      marking.max_dofs = affordable;
    return refine_carrying(criteria, marking, true);
  }


  template <int dim>
  bool
  FoslsProblem<dim>::reference_pending() const
  {
    // (not after a solve that did not converge: the loop ends there)
    return parameters.adaptivity.reference_refinements > 0 && !reference_solved &&
           steps.size() > 0 && steps.back().converged;
  }


  template <int dim>
  void
  FoslsProblem<dim>::refine_for_reference()
  {
    // every cell, as often as asked, whatever the DoF budget; the solution
    // is carried from one refinement to the next (it starts the reference
    // solve)
    Parameters::Adaptivity everywhere;
    everywhere.steps    = 1;
    everywhere.marking  = Parameters::Adaptivity::Marking::fixed_fraction;
    everywhere.fraction = 1;
    everywhere.max_dofs = 0;
    for (unsigned int r = 0; r < parameters.adaptivity.reference_refinements; ++r)
      {
        Vector<float> criteria(discretization->get_triangulation().n_active_cells());
        criteria = 1;
        refine_carrying(criteria, everywhere, r == 0);
      }
    reference_solved = true;
  }


  template <int dim>
  bool
  FoslsProblem<dim>::refine_carrying(const Vector<float> &         criteria,
                                     const Parameters::Adaptivity &marking,
                                     const bool                    from_solution)
  {
    TimerOutput::Scope t(timer, "Refinement");
    Timer              wall;
    if (from_solution)
      {
        carried = solution;
        discretization->rotate_to_cartesian(discretization->finest_level(), carried);
        carried = discretization->to_active(carried);
      }
    std::vector<LevelVector *> functions{&carried};
    for (auto &s : step_solutions)
      functions.push_back(&s);
    const bool refined = discretization->refine(criteria, marking, functions);
    if (refined)
      {
        // the solver's hierarchy refers to the levels just replaced (freed
        // before the next one is built); the uniform levels' DoFs were
        // distributed again, and a replicated mesh, partitioned anew,
        // numbers them anew, so their prolongations are built again
        solver.reset();
        transfer = std::make_unique<LevelTransfer<dim>>(*discretization);
      }
    time_setup += wall.wall_time();
    return refined;
  }


  template <int dim>
  void
  FoslsProblem<dim>::start_from_carried()
  {
    TimerOutput::Scope t(timer, "Initial guess");
    const unsigned int L    = discretization->finest_level();
    const auto &       fine = discretization->level(L);
    guess_record            = {}; // (no coarser solves)
    solution.reinit(qp.partitioner);
    solution.copy_locally_owned_data_from(carried);
    update_ghosts(solution);
    for (const auto &hanging : fine.hanging)
      solution.local_element(hanging.first) = 0.;
    discretization->rotate_to_normal_tangential(L, solution);
    // the new boundary vertices of a refined mesh take the Dirichlet data
    // and the contact bounds there, which the interpolant need not meet
    pcout << "Initial guess: the solution on the previous mesh, interpolated; it violates "
             "the constraints (Dirichlet values, contact bounds) by "
          << std::scientific << std::setprecision(3)
          << qp.max_violation(solution) * scene.scaling().length << std::defaultfloat
          << " (projected onto them)" << std::endl;
  }


  template <int dim>
  void
  FoslsProblem<dim>::finish(OutputDirectory &output)
  {
    TimerOutput::Scope                 t(timer, "Output");
    std::map<std::string, std::string> extra_files;
    if (parameters.adaptivity.enabled())
      {
        pcout << "Adaptive loop: " << adaptive_rows() << " meshes; stopped as " << adaptive_stop
              << std::endl;
        summary["adaptive_steps"] = steps.json(adaptive_rows());
        summary["adaptive_stop"]  = "\"" + adaptive_stop + "\"";
        extra_files["adaptive_steps.csv"] = steps.csv(adaptive_rows());
      }
    if (load_path())
      {
        summary["load_steps"]         = load_steps.json();
        extra_files["load_steps.csv"] = load_steps.csv();
      }
    Postprocessor<dim>(*discretization, parameters, friction_terms())
      .write(solution, *monitor, summary, used_parameters, extra_files, output);
    pcout << "Output written to " << parameters.output.directory << "/" << std::endl;
  }


  template <int dim>
  void
  FoslsProblem<dim>::stop_interrupted(OutputDirectory &output)
  {
    const std::string signal =
      Interruption::signal_name().empty() ? "a signal" : Interruption::signal_name();
    if (!finished)
      throw InterruptedRun("interrupted by " + signal +
                           " before the first solve finished: no output written");
    const std::string  kind = load_path() ? "load" : "adaptive";
    const unsigned int n_finished = load_path() ? load_steps.size() : steps.size();
    // (the step under way: the next one, or the first load step again on
    // a refined mesh)
    const unsigned int under_way =
      !load_path() ? steps.size() :
      start == Start::refined && load_step == 0 ? 1 : n_finished + 1;
    pcout << "Interrupted by " << signal << ": publishing the " << n_finished << " finished "
          << kind << " step(s)" << std::endl;
    summary                = finished->summary;
    summary["interrupted"] = "\"" + signal + "\"";
    std::map<std::string, std::string> tables;
    if (load_path())
      {
        summary["load_steps"]    = load_steps.json();
        tables["load_steps.csv"] = load_steps.csv();
      }
    if (parameters.adaptivity.enabled())
      {
        if (load_step == 0)
          adaptive_stop = "interrupted by " + signal;
        summary["adaptive_steps"]    = steps.json(adaptive_rows());
        summary["adaptive_stop"]     = "\"" + adaptive_stop + "\"";
        tables["adaptive_steps.csv"] = steps.csv(adaptive_rows());
      }
    Postprocessor<dim>(*discretization, parameters, friction_terms())
      .write(finished->contact_table,
             finished->convergence,
             summary,
             used_parameters,
             tables,
             output);
    // (the screen counts load steps from 1, adaptive steps from 0, the
    // first mesh)
    throw InterruptedRun("interrupted by " + signal + " in " + kind + " step " +
                         std::to_string(under_way) + ": the " + std::to_string(n_finished) +
                         " finished step(s) are written to " +
                         parameters.output.directory + "/, summary.json has \"interrupted\"");
  }


  template <int dim>
  void
  FoslsProblem<dim>::record_memory(const std::string &phase)
  {
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    // (deal.II's MemoryStats has no RssFile: the file-backed pages, those of
    // the program and its libraries (doc/performance.md, section 5); read
    // where the kernel reports it, 0 where it does not)
    double        rss_file_kb = 0.;
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("RssFile:", 0) == 0)
        rss_file_kb = std::atof(line.c_str() + 8);
    const MPI_Comm comm = MPI_COMM_WORLD;
    // resident memory summed over the processes, after the phase and at its
    // peak so far; the growth from one phase to the next is what it kept
    phase_memory.push_back({phase,
                            Utilities::MPI::sum(memory.VmRSS / 1024., comm),
                            Utilities::MPI::sum(memory.VmHWM / 1024., comm),
                            Utilities::MPI::sum(rss_file_kb / 1024., comm)});
  }


  template <int dim>
  std::string
  FoslsProblem<dim>::run()
  {
    // an unusable output directory is found before the work, not after it
    OutputDirectory output(parameters.output.directory, MPI_COMM_WORLD);
    // (once the output is published, a signal no longer changes the run)
    bool published = false;
    // one line as each phase ends, so that a long run shows where it is
    // (a SIGTERM or SIGINT is heeded as a phase ends: the solvers stop
    // their iteration for it, the other phases are short)
    const auto phase = [&](const char *name, const auto &work) {
      Timer wall;
      work();
      pcout << name << " ... " << std::fixed << std::setprecision(2) << wall.wall_time()
            << " s" << std::defaultfloat << std::endl;
      record_memory(name);
      if (!published && Interruption::requested(MPI_COMM_WORLD))
        stop_interrupted(output);
    };
    phase("Setup: mesh, DoFs, levels", [&] { setup(); });
    phase("Functional weights", [&] { choose_weights(); });
    for (step = 0;; ++step)
      {
        Timer step_wall;
        if (load_path() && start != Start::refined)
          {
            pcout << "Load step " << load_step + 1 << " of " << parameters.data.n_load_steps()
                  << ":";
            for (const auto &[name, value] : parameters.data.step_overrides(load_step))
              pcout << ' ' << name << " = " << value;
            pcout << std::endl;
          }
        phase("Assembly", [&] { assemble(); });
        phase("Checks: data, rigid motions, definiteness", [&] { check_problem(); });
        phase("Initial guess", [&] {
          start == Start::first   ? make_initial_guess() :
          start == Start::refined ? start_from_carried() :
                                    start_load_step();
        });
        phase("Setup: solver", [&] { setup_solver(); });
        phase("Solve", [&] { solve(); });
        // (the files of the whole run with the last step's; the adaptive
        // loop runs on the first step of a load path)
        bool further = false, next_load = false;
        phase("Output", [&] {
          output_step(output);
          steps.set_step_time(step_wall.wall_time());
          further = load_step == 0 && !reference_solved &&
                    steps.go_on(parameters.adaptivity, adaptive_stop);
          // (a load step that did not converge ends the path: the next
          // would start from an unconverged state)
          next_load = load_step + 1 < parameters.data.n_load_steps() && monitor->converged();
          if (!further && !reference_pending() && !next_load)
            {
              finish(output);
              published = true;
            }
        });
        bool refined = false;
        if (further)
          {
            phase("Refinement", [&] {
              refined = refine();
              if (refined)
                start = Start::refined;
            });
            if (!refined)
              adaptive_stop = memory_bounds_refinement ?
                                "the next mesh might not fit into the memory available" :
                                "the next mesh could have more than Adaptivity/Max DoFs DoFs";
          }
        if (!refined && next_load)
          {
            phase("Load step", [&] {
              next_load_step();
              start = Start::load_step;
            });
            continue;
          }
        if (!refined && reference_pending())
          {
            phase("Refinement", [&] {
              refine_for_reference();
              start = Start::refined;
            });
            refined = true;
            pcout << "The reference: the last mesh refined everywhere "
                  << parameters.adaptivity.reference_refinements << " time(s)" << std::endl;
          }
        if (!refined)
          {
            if (!published)
              phase("Output", [&] {
                finish(output);
                published = true;
              });
            break;
          }
        const auto &fine = discretization->level(discretization->finest_level());
        pcout << "Adaptive step " << step + 1 << ": "
              << discretization->get_triangulation().n_global_active_cells() << " cells, "
              << fine.n_dofs << " DoFs, " << discretization->get_triangulation().n_global_levels()
              << " mesh levels" << std::endl;
      }

    if (parameters.output.verbose)
      {
        timer.print_summary();
        // the parts of the solve (inside the section "Solve")
        const auto parts = solver->statistics().sections;
        if (!parts.empty())
          {
            pcout << "| Parts of the section Solve                | no. calls |  wall time |"
                  << std::endl;
            for (const auto &[name, time] : parts)
              pcout << "| " << std::left << std::setw(42) << name << "| " << std::right
                    << std::setw(9) << time.calls << " | " << std::setw(9)
                    << std::setprecision(3) << time.seconds << "s |" << std::endl;
            pcout << std::endl;
          }
      }
    return monitor->why_not_converged();
  }

  template class FoslsProblem<2>;
  template class FoslsProblem<3>;
} // namespace FoslsContact
