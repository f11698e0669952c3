#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/build_info.h>
#include <fosls_contact/fosls_problem.h>
#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/output/hertz_comparison.h>
#include <fosls_contact/output/json.h>
#include <fosls_contact/output/postprocessor.h>
#include <fosls_contact/qp/definiteness_check.h>
#include <fosls_contact/qp/gathered_qp.h>
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/monotone_multigrid.h>
#include <fosls_contact/solvers/projected_gauss_seidel.h>

#include <iomanip>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    const auto number = json_number;

    const char *
    solver_name(const Parameters::Solver::Type type)
    {
      switch (type)
        {
          case Parameters::Solver::Type::monotone_multigrid:
            return "monotone multigrid";
          case Parameters::Solver::Type::active_set:
            return "active set";
          default:
            return "projected gauss seidel";
        }
    }
  } // namespace


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
    discretization = std::make_unique<Discretization<dim>>(scene,
                                                          parameters.geometry.levels,
                                                          MPI_COMM_WORLD);
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
  FoslsProblem<dim>::assemble()
  {
    TimerOutput::Scope t(timer, "Assembly");
    Timer              wall;
    const unsigned int L = discretization->finest_level();
    qp.reinit(discretization->level(L));
    FoslsAssembler<dim>(*discretization, parameters.weights)
      .assemble(L, qp);
    time_setup += wall.wall_time();
  }


  template <int dim>
  void
  FoslsProblem<dim>::check_data()
  {
    // The data enter the problem as fixed values (Dirichlet values at the
    // vertices, tractions at the faces), bounds (the gap at the contact
    // vertices) and the right-hand side (the body force); a data
    // expression that is NaN or Inf somewhere shows there, and is named
    // here instead of as a NaN iterate later.
    const auto &       fine = discretization->level(discretization->finest_level());
    std::vector<bool>  displacement(fine.n_local(), false);
    for (const auto &[vertex, dofs] : fine.vertex_dofs)
      for (const auto dof : dofs)
        displacement[dof] = true;
    enum : unsigned int
    {
      dirichlet = 1,
      traction  = 2,
      gap       = 4,
      load      = 8
    };
    unsigned int bad = 0;
    for (unsigned int i = 0; i < qp.n_owned(); ++i)
      {
        if (qp.role[i] == DoFRole::fixed && !std::isfinite(qp.fixed_values.local_element(i)))
          bad |= displacement[i] ? dirichlet : traction;
        if (qp.role[i] == DoFRole::bounded && !std::isfinite(qp.upper_bounds.local_element(i)))
          bad |= gap;
        if (!std::isfinite(qp.rhs.local_element(i)))
          bad |= load;
      }
    if (!std::isfinite(qp.constant))
      bad |= load;
    // (every process takes the same decision)
    for (unsigned int flag = 1; flag <= load; flag *= 2)
      if (Utilities::MPI::max(bad & flag, discretization->get_communicator()) != 0)
        bad |= flag;
    const std::string what = (bad & dirichlet) ? "Data/Dirichlet values" :
                             (bad & traction)  ? "Data/Traction" :
                             (bad & gap)       ? "Data/Gap" :
                                                 "Data/Body force";
    AssertThrow(bad == 0,
                ExcMessage("parameter '" + what + "' is not finite (NaN or Inf) " +
                           ((bad & dirichlet) ? "at a vertex of the Dirichlet boundary" :
                            (bad & traction)  ? "on a face of the Neumann boundary" :
                            (bad & gap)       ? "at a vertex of the contact boundary" :
                                                "somewhere in the body")));
  }


  template <int dim>
  void
  FoslsProblem<dim>::check_rigid_motions()
  {
    // The rigid motions: translations and rotations about the centre of
    // the coarse mesh, with stress 0, in the DoF basis of the finest
    // level (normal-tangential at the contact DoFs).
    const unsigned int L    = discretization->finest_level();
    const auto &       fine = discretization->level(L);
    // (the coarse cells are the same on every process)
    Point<dim>   centre;
    unsigned int n_vertices = 0;
    for (const auto &cell : discretization->get_triangulation().cell_iterators_on_level(0))
      for (const unsigned int v : cell->vertex_indices())
        {
          centre += cell->vertex(v);
          ++n_vertices;
        }
    centre /= n_vertices;
    std::vector<std::string> names;
    const char *             axis[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back(std::string("translation in ") + axis[d]);
    std::vector<std::pair<unsigned int, unsigned int>> rotations; // (i, j): u_i = -x_j, u_j = x_i
    if (dim == 2)
      rotations = {{0, 1}};
    else
      rotations = {{1, 2}, {2, 0}, {0, 1}};
    for (unsigned int r = 0; r < rotations.size(); ++r)
      names.push_back(std::string("rotation about ") +
                      (dim == 2 ? "the centre" : axis[3 - rotations[r].first - rotations[r].second]));
    std::vector<LevelVector> modes(names.size(), qp.new_vector());
    for (const auto &cell : discretization->get_dof_handler().mg_cell_iterators_on_level(L))
      if (Discretization<dim>::is_present(cell))
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto &dofs = fine.vertex_dofs.at(cell->vertex_index(v));
            const auto  x    = cell->vertex(v) - centre;
            for (unsigned int d = 0; d < dim; ++d)
              modes[d].local_element(dofs[d]) = 1.;
            for (unsigned int r = 0; r < rotations.size(); ++r)
              {
                const auto [i, j] = rotations[r];
                modes[dim + r].local_element(dofs[i]) = -x[j];
                modes[dim + r].local_element(dofs[j]) = x[i];
              }
          }
    for (auto &mode : modes)
      discretization->rotate_to_normal_tangential(L, mode);
    // free: round-off (measured: 7e-17 on the square with a roller on top,
    // 4e-16 on the cube held in z only); held: the energy of the cut-off
    // boundary layer, O(h) (measured: 3e-4 on the square's level 9, 2e-4 on
    // the half disc with 5 levels and Grading 3, 6e-3 on the cube's level 5)
    const double   threshold = 1e-10;
    Vector<double> coefficients;
    const double   energy =
      DefinitenessCheck::least_mode_energy(qp, modes, threshold, coefficients);
    if (energy > threshold)
      return;
    std::string free_modes;
    for (unsigned int m = 0; m < names.size(); ++m)
      if (std::abs(coefficients[m]) > 0.1)
        free_modes += (free_modes.empty() ? "" : " + ") + names[m];
    AssertThrow(false,
                ExcMessage("the boundary conditions leave a rigid motion free (" + free_modes +
                           ", relative energy " + number(energy) +
                           "): the functional's quadratic form does not change along it "
                           "and its matrix is singular, which contact, one-sided, does not "
                           "cure; prescribe the motion on some boundary ('Boundary "
                           "conditions/Dirichlet boundary ids' and 'Dirichlet components')"));
  }


  template <int dim>
  void
  FoslsProblem<dim>::check_definiteness()
  {
    const auto &w = parameters.weights;
    if (!scene.has_contact() || w.c_compl == 0 ||
        parameters.solver.definiteness_max_dofs == 0)
      return;
    TimerOutput::Scope t(timer, "Definiteness check");
    Timer              wall;
    // The finest level small enough; indefinite there means indefinite on
    // all finer levels, as the spaces are nested.
    int level = discretization->finest_level();
    while (level >= 0 &&
           discretization->level(level).n_dofs > parameters.solver.definiteness_max_dofs)
      --level;
    if (level < 0)
      {
        pcout << "Definiteness check skipped: even level 1 has more than "
              << parameters.solver.definiteness_max_dofs << " DoFs" << std::endl;
        return;
      }
    // on the first process, on the gathered problem of that level
    DefinitenessCheck result;
    auto              check = [&](const ConstrainedQP &level_qp) {
      const GatheredQP gathered(level_qp);
      if (gathered.here())
        result = DefinitenessCheck::run(gathered.qp());
      result.min_relative_eigenvalue =
        Utilities::MPI::broadcast(discretization->get_communicator(),
                                  result.min_relative_eigenvalue,
                                  0);
    };
    if (static_cast<unsigned int>(level) == discretization->finest_level())
      check(qp);
    else
      {
        ConstrainedQP coarse;
        coarse.reinit(discretization->level(level));
        FoslsAssembler<dim>(*discretization, w)
          .assemble(level, coarse);
        check(coarse);
      }
    time_setup += wall.wall_time();
    pcout << "Definiteness check on level " << level + 1
          << ": smallest relative eigenvalue of the contact Schur complement = "
          << std::setprecision(4) << result.min_relative_eigenvalue << std::endl;
    std::ostringstream weights;
    weights << "C_eq = " << w.c_eq << ", C_const = " << w.c_const
            << ", C_compl = " << w.c_compl;
    AssertThrow(result.definite(),
                ExcMessage("the functional is indefinite for " + weights.str() +
                           " (smallest relative eigenvalue of the contact "
                           "Schur complement " +
                           number(result.min_relative_eigenvalue) +
                           " on level " + std::to_string(level + 1) +
                           "): decrease 'Functional weights/C_compl' or "
                           "increase C_eq/C_const (paper eq. 10)"));
  }


  template <int dim>
  std::unique_ptr<QPSolver>
  FoslsProblem<dim>::make_solver(const ConstrainedQP &level_qp,
                                 const unsigned int   level) const
  {
    switch (parameters.solver.type)
      {
        case Parameters::Solver::Type::active_set:
          return std::make_unique<ActiveSetDirect>();
        case Parameters::Solver::Type::projected_gauss_seidel:
          return std::make_unique<ProjectedGaussSeidel>(discretization->sweep_order(level));
        default:
          {
            return std::make_unique<MonotoneMultigrid<dim>>(
              *discretization, *transfer, level, level_qp.sparsity, parameters.solver);
          }
      }
  }


  template <int dim>
  LevelVector
  FoslsProblem<dim>::prolongate_rotated(const unsigned int to_level,
                                        const LevelVector &coarse) const
  {
    // (a rotation block is the DoFs of one vertex or face, of one owner:
    // the product brings the owners' rotated values to the ghost copies;
    // the owned entries of the result are valid)
    LevelVector cartesian(coarse), fine(discretization->level(to_level).partitioner);
    discretization->rotate_to_cartesian(to_level - 1, cartesian);
    transfer->prolongate(to_level, fine, cartesian);
    discretization->rotate_to_normal_tangential(to_level, fine);
    return fine;
  }


  template <int dim>
  LevelVector
  FoslsProblem<dim>::solve_on_level(const unsigned int level, const LevelVector *start) const
  {
    ConstrainedQP level_qp;
    level_qp.reinit(discretization->level(level));
    FoslsAssembler<dim>(*discretization, parameters.weights)
      .assemble(level, level_qp);
    LevelVector x = level_qp.new_vector();
    if (start)
      x = *start;
    ConditionalOStream quiet(std::cout, false);
    Monitor            level_monitor(level_qp,
                                parameters.solver,
                                quiet,
                                "initial guess (the solution on level " +
                                  std::to_string(level + 1) + ")");
    if (level == 0)
      ActiveSetDirect().solve(level_qp, x, level_monitor);
    else
      make_solver(level_qp, level)->solve(level_qp, x, level_monitor);
    return x;
  }


  template <int dim>
  void
  FoslsProblem<dim>::make_initial_guess()
  {
    TimerOutput::Scope t(timer, "Initial guess");
    const unsigned int L = discretization->finest_level();
    solution.reinit(qp.partitioner);
    using IG = Parameters::Solver::InitialGuess;
    switch (parameters.solver.initial_guess)
      {
        case IG::zero:
          break;
        case IG::coarse_solution:
          {
            // paper section 7: the exact level-1 solution, interpolated
            LevelVector x = solve_on_level(0, nullptr);
            for (unsigned int l = 1; l <= L; ++l)
              x = prolongate_rotated(l, x);
            solution = x;
            break;
          }
        case IG::nested_iteration:
          {
            LevelVector x = solve_on_level(0, nullptr);
            for (unsigned int l = 1; l < L; ++l)
              {
                x = prolongate_rotated(l, x);
                x = solve_on_level(l, &x);
              }
            if (L > 0)
              solution = prolongate_rotated(L, x);
            else
              solution = x;
            break;
          }
        case IG::expression:
          {
            const auto &fine = discretization->level(L);
            Vector<double> values(dim);
            for (const auto &cell : discretization->get_dof_handler()
                                      .mg_cell_iterators_on_level(L))
              if (Discretization<dim>::is_present(cell))
                for (const unsigned int v : cell->vertex_indices())
                  {
                    scene.initial_displacement()->vector_value(cell->vertex(v), values);
                    const auto &dofs = fine.vertex_dofs.at(cell->vertex_index(v));
                    for (unsigned int k = 0; k < dim; ++k)
                      solution.local_element(dofs[k]) = values[k];
                  }
            discretization->rotate_to_normal_tangential(L, solution);
            AssertThrow(std::isfinite(solution.l2_norm()),
                        ExcMessage("parameter 'Data/Initial displacement' is not finite (NaN "
                                   "or Inf) at a vertex"));
            break;
          }
      }
    // fixed values are simply set; a penetrating start is worth a note
    double penetration = 0;
    for (unsigned int i = 0; i < qp.n_owned(); ++i)
      if (qp.role[i] == DoFRole::bounded)
        penetration = std::max(penetration,
                               solution.local_element(i) - qp.upper_bounds.local_element(i));
    penetration = Utilities::MPI::max(penetration, qp.get_communicator());
    // (a start on its bounds up to round-off is no news)
    constexpr double round_off = 1e-12;
    if (penetration > round_off)
      pcout << "Initial guess violates the contact constraints by "
            << std::scientific << std::setprecision(3)
            << penetration * scene.scaling().length
            << std::defaultfloat << ": projected onto the feasible set"
            << std::endl;
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
    solver = make_solver(qp, discretization->finest_level());
    time_setup += wall.wall_time();
  }


  template <int dim>
  void
  FoslsProblem<dim>::solve()
  {
    TimerOutput::Scope t(timer, "Solve");
    Timer              wall;
    monitor = std::make_unique<Monitor>(qp,
                                        parameters.solver,
                                        pcout,
                                        solver_name(parameters.solver.type));
    monitor->set_functional_unit(scene.scaling().functional(dim));
    const CommunicationCounter before = communication();
    solver->solve(qp, solution, *monitor);
    time_solve          = wall.wall_time();
    solve_communication = {communication().exchanges - before.exchanges,
                           communication().values - before.values};

    const KKTResidual kkt = qp.kkt_residual(solution);
    pcout << "KKT residuals: stationarity " << std::scientific
          << std::setprecision(3) << kkt.stationarity << ", feasibility "
          << kkt.feasibility << ", complementarity " << kkt.complementarity
          << std::defaultfloat << std::endl;
    pcout << (monitor->converged() ? "Converged" : "NOT converged") << " after "
          << monitor->iterations() << " iterations"
          << (monitor->stopped_at_round_off() ?
                " (corrections at their round-off floor)" :
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
  FoslsProblem<dim>::output_results(OutputDirectory &output)
  {
    TimerOutput::Scope   t(timer, "Output");
    Summary              summary = cost_summary();
    Postprocessor<dim>   post(*discretization, parameters);
    const LevelVector    cartesian = post.solution_in_scene_units(solution);
    const Tensor<1, dim> force     = post.contact_force(cartesian);
    ErrorIndicators<dim> indicators(*discretization, parameters.weights);
    indicators.compute(solution);
    add_solver_summary(summary);
    const FunctionalValue J = add_solution_summary(summary, post, cartesian, force, indicators);
    if (parameters.hertz.shape != Parameters::HertzComparison::Shape::none &&
        scene.has_contact())
      add_hertz_comparison(summary, post, force);
    if (scene.has_exact_solution())
      add_errors(summary, post, cartesian);

    pcout << "Functional J = " << std::scientific << std::setprecision(6)
          << J.total << " (eq " << J.eq << ", const " << J.constitutive
          << ", compl " << J.complementarity << ")" << std::defaultfloat
          << std::endl;
    if (scene.has_contact())
      {
        pcout << "Contact force =";
        for (unsigned int d = 0; d < dim; ++d)
          pcout << ' ' << std::setprecision(8) << force[d];
        pcout << std::defaultfloat << std::endl;
      }
    post.write(solution, *monitor, summary, used_parameters, indicators, output);
    pcout << "Output written to " << parameters.output.directory << "/"
          << std::endl;
  }


  template <int dim>
  typename FoslsProblem<dim>::Summary
  FoslsProblem<dim>::cost_summary() const
  {
    // first, so that the peak memory is that of the solve, not of the
    // output's own vectors
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const MPI_Comm comm    = discretization->get_communicator();
    const double   peak_mb = memory.VmHWM / 1024.;

    Summary summary;
    summary["git_revision"]    = "\"" + BuildInfo::git_revision() + "\"";
    summary["deal_ii_version"] = "\"" + BuildInfo::deal_ii_version() + "\"";
    summary["time_setup_s"]    = number(time_setup);
    summary["time_solve_s"]    = number(time_solve);
    // peak resident memory: all processes together, and the largest one
    summary["peak_rss_mb"]             = number(Utilities::MPI::sum(peak_mb, comm));
    summary["peak_rss_mb_per_process"] = number(Utilities::MPI::max(peak_mb, comm));
    std::vector<std::string> phases;
    for (const auto &[phase, rss_mb, peak_rss_mb] : phase_memory)
      phases.push_back("{\"phase\": \"" + phase + "\", \"rss_mb\": " + number(rss_mb) +
                       ", \"peak_rss_mb\": " + number(peak_rss_mb) + "}");
    summary["memory_by_phase"] = json_array(phases);
    summary["mpi_processes"] = std::to_string(Utilities::MPI::n_mpi_processes(comm));
    // communication of the solve: point-to-point exchanges of the busiest
    // process, values sent by all; and the ghost DoFs per level (all
    // processes), the surface the exchanges move
    summary["solve_exchanges"] =
      std::to_string(Utilities::MPI::max(solve_communication.exchanges, comm));
    summary["solve_values_sent"] =
      std::to_string(Utilities::MPI::sum(solve_communication.values, comm));
    std::vector<std::string> ghosts;
    for (unsigned int l = 0; l < discretization->n_levels(); ++l)
      ghosts.push_back(std::to_string(
        Utilities::MPI::sum(discretization->level(l).partitioner->n_ghost_indices(), comm)));
    summary["ghost_dofs_per_level"] = json_array(ghosts);

    // wall seconds of every TimerOutput section finished so far (the output
    // section itself is still running) and of the parts of the solve
    auto times = timer.get_summary_data(TimerOutput::total_wall_time);
    for (const auto &[name, time] : solver->statistics().sections)
      times[name] = time.seconds;
    std::string sections = "{";
    for (const auto &[name, seconds] : times)
      if (name != "Output")
        sections += std::string(sections.size() > 1 ? ", " : "") + "\"" + name +
                    "\": " + number(seconds);
    summary["time_sections_s"] = sections + "}";
    return summary;
  }


  template <int dim>
  void
  FoslsProblem<dim>::add_solver_summary(Summary &summary) const
  {
    summary["dimension"]  = std::to_string(dim);
    summary["dofs"]       = std::to_string(qp.size());
    summary["levels"]     = std::to_string(discretization->n_levels());
    summary["solver"]     = std::string("\"") + solver_name(parameters.solver.type) + "\"";
    summary["iterations"] = std::to_string(monitor->iterations());
    summary["converged"]  = monitor->converged() ? "true" : "false";
    summary["stopped_at_round_off"] = monitor->stopped_at_round_off() ? "true" : "false";
    summary["stop_reason"]          = "\"" + monitor->stop_reason() + "\"";
    summary["rate_asymptotic"]      = number(monitor->asymptotic_rate());
    summary["cycles"]               = std::to_string(monitor->cycles());
    summary["rate_per_cycle"]       = number(monitor->rate_per_cycle());
    summary["kkt_residual"]         = number(qp.kkt_residual(solution).max());
    summary["max_violation"]        = number(qp.max_violation(solution));
    summary["active"]               = std::to_string(qp.n_active(solution));
    summary["energy_increases"]     = std::to_string(monitor->energy_increases());
    summary["feasibility_dampings"] = std::to_string(monitor->feasibility_dampings());
    summary["h_ratio_coarse"]       = number(discretization->coarse_mesh_ratio());

    const SolverStatistics statistics = solver->statistics();
    const auto &           mg         = statistics.multilevel;
    if (!mg)
      return;
    std::vector<std::string> colors;
    for (const unsigned int c : mg->patch_colors)
      colors.push_back(std::to_string(c));
    summary["patch_colors"] = json_array(colors);
    // where the cycles' time goes: visits and wall time of every level
    // without the coarser levels it visits
    std::vector<std::string> dofs, visits, seconds;
    for (unsigned int l = 0; l < mg->level_times.size(); ++l)
      {
        dofs.push_back(std::to_string(discretization->level(l).n_dofs));
        visits.push_back(std::to_string(mg->level_times[l].calls));
        seconds.push_back(number(mg->level_times[l].seconds));
      }
    summary["level_dofs"]   = json_array(dofs);
    summary["level_visits"] = json_array(visits);
    summary["level_time_s"] = json_array(seconds);
    if (parameters.solver.check_coarse_defects)
      {
        summary["coarse_defect_checks"]     = std::to_string(mg->coarse_defect_checks);
        summary["coarse_defect_difference"] = number(mg->coarse_defect_difference);
      }
  }


  template <int dim>
  FunctionalValue
  FoslsProblem<dim>::add_solution_summary(Summary &                  summary,
                                          const Postprocessor<dim> & post,
                                          const LevelVector &        cartesian,
                                          const Tensor<1, dim> &     force,
                                          const ErrorIndicators<dim> &indicators) const
  {
    // J in the scene's units (Scaling::functional())
    const FunctionalValue J_hat  = qp.parts(solution);
    const double          J_unit = scene.scaling().functional(dim);
    FunctionalValue       J      = J_hat;
    J.total *= J_unit;
    J.eq *= J_unit;
    J.constitutive *= J_unit;
    J.complementarity *= J_unit;
    summary["functional"]               = number(J.total);
    summary["functional_eq"]            = number(J.eq);
    summary["functional_const"]         = number(J.constitutive);
    summary["functional_compl"]         = number(J.complementarity);
    summary["functional_dimensionless"] = number(J_hat.total);
    summary["scaling"] = "{\"length\": " + number(scene.scaling().length) +
                         ", \"stress\": " + number(scene.scaling().stress) + "}";
    const auto &m      = parameters.material;
    summary["material"] = "{\"mu\": " + number(m.mu) + ", \"lambda\": " +
                          (std::isinf(m.lambda) ? std::string("\"inf\"") : number(m.lambda)) +
                          ", \"E\": " + number(m.youngs_modulus) +
                          ", \"nu\": " + number(m.poisson_ratio) + "}";
    std::vector<std::string> f;
    for (unsigned int d = 0; d < dim; ++d)
      f.push_back(number(force[d]));
    summary["contact_force"] = json_array(f);
    // the error indicators: the cellwise parts of J (their sum)
    summary["error_indicators"] =
      "{\"sum\": " + number(J_unit * indicators.total()) +
      ", \"max\": " + number(std::sqrt(J_unit * indicators.max_squared())) +
      ", \"cells\": " + std::to_string(discretization->get_triangulation().n_global_active_cells()) +
      ", \"cells_for_half_of_J\": " + std::to_string(indicators.cells_for_half()) + "}";
    const FieldMaxima maxima    = post.field_maxima(cartesian);
    summary["max_displacement"] = number(maxima.displacement);
    summary["max_von_mises"]    = number(maxima.von_mises);
    return J;
  }


  template <int dim>
  void
  FoslsProblem<dim>::add_hertz_comparison(Summary &                 summary,
                                          const Postprocessor<dim> &post,
                                          const Tensor<1, dim> &    force) const
  {
    // (the contact table is gathered on the first process)
    const auto rows = ContactTable<dim>(*discretization).rows(solution);
    Point<dim> contact_point;
    for (unsigned int d = 0; d < dim; ++d)
      contact_point[d] = parameters.hertz.contact_point[d] / scene.scaling().length;
    HertzComparison<dim> hertz(parameters.hertz,
                               parameters.material,
                               scene.obstacle_normal(contact_point));
    hertz.evaluate(force, rows);
    summary["hertz"] = hertz.json();
    pcout << hertz.report() << std::endl;
  }


  template <int dim>
  void
  FoslsProblem<dim>::add_errors(Summary &                 summary,
                                const Postprocessor<dim> &post,
                                const LevelVector &       cartesian) const
  {
    const ErrorNorms e = post.errors(cartesian);
    AssertThrow(std::isfinite(e.u_l2) && std::isfinite(e.u_h1_semi),
                ExcMessage("parameter 'Data/Exact displacement' is not finite (NaN or Inf) "
                           "somewhere on the mesh: its error norms are not finite"));
    AssertThrow(std::isfinite(e.sigma_l2) && std::isfinite(e.sigma_div),
                ExcMessage("parameter 'Data/Exact stress' is not finite (NaN or Inf) "
                           "somewhere on the mesh: its error norms are not finite"));
    summary["error_u_l2"]       = number(e.u_l2);
    summary["error_u_h1"]       = number(e.u_h1());
    summary["error_sigma_l2"]   = number(e.sigma_l2);
    summary["error_sigma_hdiv"] = number(e.sigma_hdiv());
    pcout << "Errors: |u - u_h|_H1 = " << std::scientific << std::setprecision(4) << e.u_h1()
          << ", |sigma - sigma_h|_Hdiv = " << e.sigma_hdiv() << std::defaultfloat << std::endl;
  }


  template <int dim>
  void
  FoslsProblem<dim>::record_memory(const std::string &phase)
  {
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const MPI_Comm comm = MPI_COMM_WORLD;
    // resident memory summed over the processes, after the phase and at its
    // peak so far; the growth from one phase to the next is what it kept
    phase_memory.push_back({phase,
                            Utilities::MPI::sum(memory.VmRSS / 1024., comm),
                            Utilities::MPI::sum(memory.VmHWM / 1024., comm)});
  }


  template <int dim>
  std::string
  FoslsProblem<dim>::run()
  {
    // an unusable output directory is found before the work, not after it
    OutputDirectory output(parameters.output.directory, MPI_COMM_WORLD);
    // one line as each phase ends, so that a long run shows where it is
    const auto phase = [&](const char *name, const auto &work) {
      Timer wall;
      work();
      pcout << name << " ... " << std::fixed << std::setprecision(2) << wall.wall_time()
            << " s" << std::defaultfloat << std::endl;
      record_memory(name);
    };
    phase("Setup: mesh, DoFs, levels", [&] { setup(); });
    phase("Assembly", [&] { assemble(); });
    phase("Checks: data, rigid motions, definiteness", [&] {
      check_data();
      check_rigid_motions();
      check_definiteness();
    });
    phase("Initial guess", [&] { make_initial_guess(); });
    phase("Setup: solver", [&] { setup_solver(); });
    phase("Solve", [&] { solve(); });
    phase("Output", [&] { output_results(output); });
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
    if (monitor->converged())
      return "";
    std::ostringstream why;
    if (monitor->stop_reason() == "stalled")
      why << "not converged: stalled at a rate of " << std::fixed << std::setprecision(4)
          << monitor->asymptotic_rate() << " per iteration"
          << (parameters.solver.krylov_steps == 0 ?
                " (the default solver, Solver/Krylov steps > 0, converges there)" :
                "");
    else if (monitor->stop_reason() == "diverged")
      {
        const auto &h = monitor->get_history();
        const double J_unit = scene.scaling().functional(dim);
        why << "not converged: J increased in iteration " << h.size() - 1 << " from "
            << std::scientific << std::setprecision(3) << J_unit * h[h.size() - 2].functional.total
            << " to " << J_unit * h.back().functional.total
            << ", which a monotone solver's step cannot do: its multilevel model of the "
               "functional is wrong on this mesh ('Solver/Type' = active set solves the "
               "problem directly)";
      }
    else
      why << "not converged within 'Solver/Max iterations' = "
          << parameters.solver.max_iterations;
    return why.str();
  }

  template class FoslsProblem<2>;
  template class FoslsProblem<3>;
} // namespace FoslsContact
