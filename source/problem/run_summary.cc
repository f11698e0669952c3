#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <fosls_contact/base/build_info.h>
#include <fosls_contact/base/json.h>
#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/output/contact_zone.h>
#include <fosls_contact/output/cattaneo_mindlin.h>
#include <fosls_contact/output/hertz_pressure.h>
#include <fosls_contact/problem/conditioning.h>
#include <fosls_contact/problem/run_summary.h>
#include <fosls_contact/problem/solver_choice.h>

#include <algorithm>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <tuple>

namespace FoslsContact
{
  namespace
  {
    const auto number = json_number;

    /**
     * A force for the screen: 8 significant digits, components below 1e-12
     * of @p scale (the largest force) as 0 (round-off: the screen's
     * "-9.08e-13 4089.3683" was the force (0, 4089.3683)), each in a column
     * of @p width + 1.
     */
    template <int dim>
    std::string
    force_text(const Tensor<1, dim> &f, const double scale, const int width = 15)
    {
      std::ostringstream out;
      out << std::setprecision(8);
      for (unsigned int d = 0; d < dim; ++d)
        out << ' ' << std::setw(width) << (std::abs(f[d]) < 1e-12 * scale ? 0. : f[d]);
      return out.str();
    }

    /** " mm": @p unit after a number, or nothing for an unnamed unit. */
    std::string
    suffix(const std::string &unit)
    {
      return unit.empty() ? "" : " " + unit;
    }
  } // namespace


  template <int dim>
  RunSummary<dim>::RunSummary(const Parameters::AllParameters &parameters,
                              const Scene<dim> &               scene,
                              const Discretization<dim> &      discretization,
                              const ConstrainedQP &            qp,
                              const LevelVector &              solution,
                              const QPSolver &                 solver,
                              const Monitor &                  monitor,
                              const ConditionalOStream &       pcout)
    : parameters(parameters)
    , scene(scene)
    , discretization(discretization)
    , qp(qp)
    , solution(solution)
    , solver(solver)
    , monitor(monitor)
    , pcout(pcout)
  {}


  template <int dim>
  typename RunSummary<dim>::Summary
  RunSummary<dim>::cost(const TimerOutput &             timer,
                        const double                    time_setup,
                        const double                    time_solve,
                        const std::vector<PhaseMemory> &phase_memory,
                        const CommunicationCounter &    solve_communication) const
  {
    // first, so that the peak memory is that of the solve, not of the
    // output's own vectors
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const MPI_Comm comm    = discretization.get_communicator();
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
    for (const auto &[phase, rss_mb, peak_rss_mb, rss_file_mb] : phase_memory)
      phases.push_back("{\"phase\": \"" + phase + "\", \"rss_mb\": " + number(rss_mb) +
                       ", \"peak_rss_mb\": " + number(peak_rss_mb) +
                       ", \"rss_file_mb\": " + number(rss_file_mb) + "}");
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
    for (unsigned int l = 0; l < discretization.n_levels(); ++l)
      ghosts.push_back(std::to_string(
        Utilities::MPI::sum(discretization.level(l).partitioner->n_ghost_indices(), comm)));
    summary["ghost_dofs_per_level"] = json_array(ghosts);

    // wall seconds of every TimerOutput section finished so far (the output
    // section itself is still running) and of the parts of the solve
    auto times = timer.get_summary_data(TimerOutput::total_wall_time);
    for (const auto &[name, time] : solver.statistics().sections)
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
  RunSummary<dim>::add_memory(Summary &summary, const LevelBytes &transfer_bytes) const
  {
    const SolverStatistics statistics = solver.statistics();
    std::size_t            n_levels = discretization.n_levels();
    if (statistics.multilevel)
      for (const auto &entry : statistics.multilevel->memory)
        n_levels = std::max(n_levels, entry.second.size());
    // The discretization's levels are the uniform ones and, on an
    // adaptively refined mesh, the active mesh (@p with_active, the last
    // entry): the multigrid hierarchy's finest level, below which
    // LevelMeshes adds levels of its own. The uniform levels'
    // prolongations have no entry for the active mesh.
    const auto on_hierarchy = [&](LevelBytes bytes, const bool with_active) {
      const std::size_t active = with_active ? bytes.back() : 0;
      if (with_active)
        bytes.pop_back();
      bytes.resize(n_levels, 0);
      bytes.back() += active;
      return bytes;
    };
    // the assembled problem is the finest level's
    LevelBytes problem(n_levels, 0);
    problem.back() = qp.memory_consumption();
    std::vector<std::pair<std::string, LevelBytes>> memory = {
      {"level data (coupling patterns, DoF tables, roles, bounds)",
       on_hierarchy(discretization.level_memory_consumption(), discretization.adaptive())},
      {"prolongations of the uniform levels", on_hierarchy(transfer_bytes, false)},
      {"assembled problem (A, parts of J, vectors)", problem}};
    if (statistics.multilevel)
      memory.insert(memory.end(),
                    statistics.multilevel->memory.begin(),
                    statistics.multilevel->memory.end());

    // (every process takes part in every sum, also one with no entries for
    // a level: each list has the same length on all of them)
    const MPI_Comm comm   = qp.get_communicator();
    const auto     mb     = [&](const double bytes) { return number(bytes / 1048576.); };
    std::string    totals = "{\"mesh and DoF handler\": " +
                         mb(Utilities::MPI::sum(double(discretization.mesh_memory_consumption()),
                                                comm));
    std::string by_level = "{";
    for (auto &[name, bytes] : memory)
      {
        bytes.resize(n_levels, 0);
        std::vector<double> level_bytes(bytes.begin(), bytes.end());
        Utilities::MPI::sum(level_bytes, comm, level_bytes);
        std::vector<std::string> levels;
        for (const double b : level_bytes)
          levels.push_back(mb(b));
        totals += ", \"" + name + "\": " +
                  mb(std::accumulate(level_bytes.begin(), level_bytes.end(), 0.));
        by_level += std::string(by_level.size() > 1 ? ", " : "") + "\"" + name +
                    "\": " + json_array(levels);
      }
    summary["memory_mb"]          = totals + "}";
    summary["memory_mb_by_level"] = by_level + "}";
  }


  template <int dim>
  void
  RunSummary<dim>::add_solver(Summary &summary) const
  {
    summary["dimension"]  = std::to_string(dim);
    summary["dofs"]       = std::to_string(qp.size());
    summary["levels"]     = std::to_string(discretization.n_levels());
    summary["solver"]     = std::string("\"") + SolverChoice<dim>::name(parameters.solver.type) + "\"";
    summary["iterations"] = std::to_string(monitor.iterations());
    summary["converged"]  = monitor.converged() ? "true" : "false";
    summary["stopped_at_round_off"] = monitor.stopped_at_round_off() ? "true" : "false";
    summary["stop_reason"]          = "\"" + monitor.stop_reason() + "\"";
    summary["rate_asymptotic"]      = number(monitor.asymptotic_rate());
    summary["cycles"]               = std::to_string(monitor.cycles());
    summary["rate_per_cycle"]       = number(monitor.rate_per_cycle());
    summary["kkt_residual"]         = number(qp.kkt_residual(solution).max());
    summary["max_violation"]        = number(qp.max_violation(solution));
    summary["active"]               = std::to_string(qp.n_active(solution));
    summary["energy_increases"]     = std::to_string(monitor.energy_increases());
    summary["feasibility_dampings"] = std::to_string(monitor.feasibility_dampings());
    summary["h_ratio_coarse"]       = number(discretization.coarse_mesh_ratio());

    const SolverStatistics statistics = solver.statistics();
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
        dofs.push_back(std::to_string(mg->level_dofs[l]));
        visits.push_back(std::to_string(mg->level_times[l].calls));
        seconds.push_back(number(mg->level_times[l].seconds));
      }
    summary["level_dofs"]   = json_array(dofs);
    summary["level_visits"] = json_array(visits);
    summary["level_time_s"] = json_array(seconds);
    // the solve's work in sweeps over the finest level (deterministic,
    // unlike its time)
    std::vector<std::string> sweeps;
    for (const auto n : mg->level_sweeps)
      sweeps.push_back(std::to_string(n));
    summary["level_sweeps"] = json_array(sweeps);
    summary["work_units"]   = number(mg->work_units());
    // the linear cycle as CG's preconditioner in the Newton steps
    summary["linear_steps"] = std::to_string(mg->linear_steps);
    summary["linear_rate"]  = number(mg->linear_rate());
    if (parameters.solver.check_coarse_defects)
      {
        summary["coarse_defect_checks"]     = std::to_string(mg->coarse_defect_checks);
        summary["coarse_defect_difference"] = number(mg->coarse_defect_difference);
      }
  }


  template <int dim>
  FunctionalValue
  RunSummary<dim>::add_solution(Summary &                   summary,
                                  const Postprocessor<dim> & post,
                                  const LevelVector &        cartesian,
                                  const Tensor<1, dim> &     force,
                                  const ErrorIndicators<dim> &indicators,
                                  const FieldMaxima &         maxima) const
  {
    // J in the scene's units (ReferenceScales::functional())
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
    // the names of the units (empty: the scene's units, unnamed), and
    // those of the answers made of them
    const Parameters::UnitNames &units = parameters.scaling.unit_names;
    summary["units"] = "{\"length\": \"" + units.length + "\", \"force\": \"" + units.force +
                       "\", \"stress\": \"" + units.stress + "\", \"reported_force\": \"" +
                       units.reported_force(dim) + "\", \"contact_measure\": \"" +
                       units.contact_measure(dim) + "\", \"functional\": \"" +
                       units.functional(dim) + "\"}";
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
      ", \"cells\": " + std::to_string(discretization.get_triangulation().n_global_active_cells()) +
      ", \"cells_for_half_of_J\": " + std::to_string(indicators.cells_for_half()) + "}";
    summary["max_displacement"] = number(maxima.displacement);
    summary["max_von_mises"]    = number(maxima.von_mises);
    std::vector<std::string> where;
    for (const double x : maxima.von_mises_position)
      where.push_back(number(x));
    summary["max_von_mises_position"] = json_array(where);
    return J;
  }


  template <int dim>
  double
  RunSummary<dim>::add_error_estimate(Summary &                   summary,
                                      const Postprocessor<dim> &  post,
                                      const LevelVector &         cartesian,
                                      const ErrorIndicators<dim> &indicators) const
  {
    // J^ bounds |x - x_h|^2 from above and below in the norm of
    // H1 x H(div) of the dimensionless problem (paper section 1), whose
    // constants are of order 1 for the weights' defaults: sqrt(J^) over
    // the solution's own norm there is the relative error, within those
    // constants, in every unit system alike. (The sum of the cellwise
    // parts: the accurate value of J^, section 9 of doc/method.md.)
    LevelVector zero(cartesian);
    zero               = 0.;
    const double norm  = post.difference(cartesian, zero).scaled(scene.scaling(), dim);
    const double J_hat = std::max(indicators.total(), 0.);
    const double relative =
      norm > 0 ? std::sqrt(J_hat) / norm : std::numeric_limits<double>::infinity();
    summary["relative_error_estimate"] = number(relative);
    pcout << "Relative error estimate: sqrt(J)/|x| = " << std::scientific << std::setprecision(2)
          << relative << std::defaultfloat
          << " (in the H1 x H(div) norm of the scaled problem, in which J bounds the error "
             "from above and below)"
          << std::endl;
    return relative;
  }


  template <int dim>
  void
  RunSummary<dim>::add_forces(Summary &                                           summary,
                              const std::map<types::boundary_id, Tensor<1, dim>> &forces,
                              const Tensor<1, dim> &                              force) const
  {
    const Parameters::UnitNames &units      = parameters.scaling.unit_names;
    const std::string            force_unit = units.reported_force(dim);
    const auto                   precision  = pcout.get_stream().precision();
    double                       largest    = 0;
    Tensor<1, dim>               sum;
    for (const auto &[id, f] : forces)
      {
        largest = std::max(largest, f.norm());
        sum += f;
      }

    // one convention for all: the traction integral, the force exerted on
    // the body (the contact force is the obstacle's push, a Dirichlet id's
    // force the support's reaction, a Neumann id's the applied load)
    if (scene.has_contact())
      pcout << "Contact force =" << force_text(force, force.norm(), 0) << suffix(force_unit)
            << " (exerted on the body by the obstacle)" << std::endl;
    pcout << "Boundary forces: the integral of sigma n over each boundary id (n the body's "
             "outward normal), the force exerted on the body there"
          << (dim == 2 ? "; per unit length out of plane (plane strain)" : "") << ", in "
          << (units.named() ? force_unit :
                              std::string("the scene's units") +
                                (dim == 2 ? " (force per unit length)" : ""))
          << std::endl;
    // by condition: contact, Dirichlet (reactions), Neumann (loads)
    const std::vector<std::tuple<std::string, std::string, std::vector<unsigned int>>> kinds = {
      {"contact", "contact  ", parameters.boundary_conditions.contact_ids},
      {"dirichlet", "Dirichlet", parameters.boundary_conditions.dirichlet_ids},
      {"neumann", "Neumann  ", parameters.boundary_conditions.neumann_ids}};
    std::string json = "{";
    for (const auto &[key, label, ids] : kinds)
      {
        json += std::string(json.size() > 1 ? ", " : "") + "\"" + key + "\": {";
        std::vector<unsigned int> sorted = ids;
        std::sort(sorted.begin(), sorted.end());
        for (unsigned int i = 0; i < sorted.size(); ++i)
          {
            const Tensor<1, dim> &f = forces.at(sorted[i]);
            json += std::string(i ? ", " : "") + "\"" + std::to_string(sorted[i]) +
                    "\": " + json_vector<dim>(f);
            pcout << "  " << label << " id " << std::left << std::setw(4) << sorted[i]
                  << std::right << force_text(f, largest)
                  << (key == "dirichlet" ? "  (reaction)" : "") << std::endl;
          }
        json += "}";
      }
    summary["boundary_forces"]    = json + "}";
    summary["boundary_force_sum"] = json_vector<dim>(sum);
    pcout << std::left << std::setw(19) << "  sum" << std::right << std::setprecision(8);
    for (unsigned int d = 0; d < dim; ++d)
      pcout << ' ' << std::setw(15) << sum[d];
    pcout << std::defaultfloat << "  (the integral of div sigma: in equilibrium "
          << (scene.has_body_force() ? "minus the body force's resultant" : "0") << "; |sum| = "
          << std::setprecision(2) << (largest > 0 ? sum.norm() / largest : 0.)
          << " of the largest force)" << std::defaultfloat << std::setprecision(precision)
          << std::endl;

    if (!scene.has_contact())
      return;
    // (the contact table is gathered on the first process, which prints
    // and writes)
    const ContactZone<dim> zone(ContactTable<dim>(discretization).rows(solution));
    const char *           measure = dim == 2 ? "width" : "area";
    std::vector<std::string> peak_position;
    for (unsigned int d = 0; d < dim; ++d)
      peak_position.push_back(number(zone.peak_position()[d]));
    summary["contact_zone"] =
      std::string("{\"") + measure + "\": " + number(zone.measure()) +
      ", \"mean_pressure\": " + number(zone.mean_pressure()) +
      ", \"peak_pressure\": " + number(zone.peak_pressure()) +
      ", \"peak_position\": " + json_array(peak_position) +
      ", \"vertices_in_contact\": " + std::to_string(zone.vertices_in_contact()) +
      ", \"contact_vertices\": " + std::to_string(zone.vertices()) +
      ", \"resolved\": " + (zone.resolved() ? "true" : "false") + "}";
    pcout << "Contact zone: " << measure << ' ' << std::setprecision(6) << zone.measure()
          << suffix(units.contact_measure(dim)) << " (" << zone.vertices_in_contact() << " of "
          << zone.vertices() << " contact vertices in contact), mean pressure "
          << zone.mean_pressure() << suffix(units.stress) << ", peak pressure "
          << zone.peak_pressure() << suffix(units.stress) << " at (";
    // (a coordinate below 1e-12 L is round-off of the mesh's mapping: 0)
    for (unsigned int d = 0; d < dim; ++d)
      pcout << (d ? ", " : "")
            << (std::abs(zone.peak_position()[d]) < 1e-12 * scene.scaling().length ?
                  0. :
                  zone.peak_position()[d]);
    pcout << ')' << suffix(units.length) << std::defaultfloat << std::setprecision(precision)
          << std::endl;
    if (!zone.resolved())
      pcout << "Warning: only " << zone.vertices_in_contact()
            << " contact vertices are in contact: the mesh does not resolve the contact zone "
               "(its measure, pressures and force are those of so few vertices, and a zone "
               "that touches a single vertex carries no force); refine the mesh where the body touches"
            << std::endl;
  }


  template <int dim>
  void
  RunSummary<dim>::add_round_off(Summary &                   summary,
                                 const double                J,
                                 const double                J_start,
                                 const ErrorIndicators<dim> &indicators) const
  {
    const IterationRecord &last     = monitor.get_history().back();
    const double           relative = last.functional_round_off /
                                std::max(std::abs(last.functional.total),
                                         std::numeric_limits<double>::min());
    summary["functional_round_off"] = number(relative);
    const bool limited              = relative > round_off_warning;
    summary["round_off_limited"]    = limited ? "true" : "false";
    if (limited)
      {
        const std::string cause =
          Conditioning<dim>::advice(parameters, scene, discretization.get_triangulation());
        std::ostringstream text;
        text << "the round-off of J is " << std::setprecision(2) << relative
             << " of J: the functional is too badly conditioned for double precision to "
                "resolve the solution to the digits asked (force and error estimate "
                "included); "
             << cause;
        pcout << "Warning: " << text.str() << std::endl;
        // (the cause text has no quotes or backslashes)
        summary["round_off_cause"] = "\"" + cause + "\"";
      }

    // J is a quadratic form of the assembled matrix, x^T A x - 2 b^T x + c;
    // the sum of the cellwise parts integrates the residuals themselves.
    // They part where the form's round-off reaches J: entries of C_eq h^-2
    // cancel in div sigma_h, so weights many orders apart or cells many
    // orders smaller than the domain part them by far more than on the
    // uniform meshes of the benchmarks (doc/performance.md, "Figures behind the code").
    // A J at the round-off of its start is no news.
    const double J_cells = indicators.total() * scene.scaling().functional(dim);
    const double gap     = std::abs(J - J_cells);
    if (gap > 1e-3 * std::abs(J_cells) && gap > 1e-12 * std::abs(J_start))
      pcout << "Note: J of the assembled quadratic form differs from the sum of its "
               "cellwise parts, "
            << std::scientific << std::setprecision(6) << J_cells << std::defaultfloat
            << ", by " << std::setprecision(2) << gap / std::abs(J_cells) << std::defaultfloat
            << " relative: its round-off reaches J ('Functional weights' many orders "
               "apart, or cells many orders smaller than the domain); the sum is the "
               "accurate value (summary.json error_indicators.sum)"
            << std::endl;
  }


  template <int dim>
  std::pair<double, double>
  RunSummary<dim>::add_hertz_comparison(
    Summary &                                            summary,
    const Tensor<1, dim> &                               force,
    const std::vector<typename ContactRow<dim>::Values> &rows) const
  {
    Point<dim> contact_point;
    for (unsigned int d = 0; d < dim; ++d)
      contact_point[d] = parameters.hertz.contact_point[d] / scene.scaling().length;
    HertzPressure<dim> hertz(parameters.hertz,
                               parameters.material,
                               scene.obstacle_normal(contact_point));
    hertz.evaluate(force, rows);
    summary["hertz"] = hertz.json();
    pcout << hertz.report() << std::endl;
    // (a cylinder in 2D or a sphere in 3D: Cattaneo and Mindlin's
    // solutions; Coulomb's f is dimensionless)
    if ((dim == 2) == (parameters.hertz.shape == Parameters::HertzComparison::Shape::cylinder) &&
        scene.friction_law() == Parameters::Friction::Law::coulomb)
      {
        CattaneoMindlin<dim> cattaneo_mindlin(hertz, scene.friction_data().value(contact_point));
        cattaneo_mindlin.evaluate(force, rows);
        summary["cattaneo_mindlin"] = cattaneo_mindlin.json();
        pcout << cattaneo_mindlin.report() << std::endl;
      }
    return {hertz.relative_pressure_error(), hertz.relative_pressure_error_boundary()};
  }


  template <int dim>
  ErrorNorms
  RunSummary<dim>::add_errors(Summary &                 summary,
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
    return e;
  }


  template class RunSummary<2>;
  template class RunSummary<3>;
} // namespace FoslsContact
