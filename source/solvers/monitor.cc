#include <fosls_contact/base/interruption.h>
#include <fosls_contact/solvers/monitor.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace FoslsContact
{
  Monitor::Monitor(const ConstrainedQP &     qp,
                   const Parameters::Solver &parameters,
                   const ConditionalOStream &pcout,
                   const std::string &       solver_name)
    : qp(qp)
    , parameters(parameters)
    , pcout(pcout)
    , solver_name(solver_name)
    , rules(parameters)
  {}


  void
  Monitor::start(const LevelVector &x)
  {
    AssertThrow(std::isfinite(x.l2_norm()),
                ExcMessage("the starting iterate is not finite"));
    timer.restart();
    history.clear();
    has_converged = at_floor = floor_stagnated = false;
    reason.clear();
    stall_error = 0;
    IterationRecord r;
    r.functional = qp.parts(x);
    active_set            = qp.active_set(x);
    active_set_changed_at = 0;
    r.active    = qp.n_active(active_set);
    r.violation = qp.max_violation(x);
    history.push_back(r);
    pcout << "  " << solver_name << ": start  J = " << std::scientific
          << std::setprecision(6) << functional_unit * r.functional.total
          << "  active = " << r.active << std::endl;
  }


  bool
  Monitor::report(const LevelVector &x, const LevelVector &x_old)
  {
    const IterationRecord &r = record(x, x_old);
    // The solution of a least-squares problem has a small energy (J(x*)
    // is the discretization error), so corrections are measured relative
    // to the first one: the criterion is an error reduction factor.
    const double norm_x = tolerance_reference();
    // Both the round-off floor and the tolerance take the rate into
    // account: at a rate rho the error is about rho/(1-rho) times the
    // correction, so where rho > 1/2 that multiple of the correction is
    // compared (rho: the larger of the last two rates, so that one lucky
    // step does not end a slow run): comparing the correction alone
    // stopped a plain W-cycle creeping at 0.992 a hundred times farther
    // from the active set solver's force (doc/performance.md, "Figures behind the code").
    // (history[0] is the start, whose rate is 0)
    const double rho    = std::max(r.rate, history[history.size() - 2].rate);
    const double factor = rho < 1. ? std::max(1., rho / (1. - rho)) :
                                     std::numeric_limits<double>::infinity();
    bool stop = at_round_off_floor(rho, factor);
    if (parameters.stopping == Parameters::Solver::Stopping::tolerance)
      stop |= r.correction * factor <= parameters.tolerance * norm_x;
    else
      stop |= rules.at_discretization_accuracy(history,
                                                    active_set_changed_at,
                                                    rate_floor,
                                                    minimum_rates);
    has_converged = stop;
    reason        = !stop                                                             ? "" :
                    at_floor                                                          ? "round-off floor" :
                    parameters.stopping == Parameters::Solver::Stopping::tolerance ? "tolerance" :
                                                                                     "discretization accuracy";
    if (!stop && detect_stalls && rules.stalled(history, active_set_changed_at, norm_x, stall_error))
      {
        stop   = true;
        reason = "stalled";
      }
    if (diverged())
      {
        has_converged = false;
        stop          = true;
        reason = "diverged";
      }
    const bool out_of_iterations = r.iteration >= parameters.max_iterations;
    if (!stop && out_of_iterations)
      reason = "iteration limit";
    // (the decision of the first process for all: the numbers it rests on
    // are sums over all processes, which MPI need not round alike on every
    // process, and a process that stops alone would wait for the others
    // in their next collective)
    const auto decision = Utilities::MPI::broadcast(
      qp.get_communicator(),
      std::make_tuple(stop, has_converged, at_floor, reason),
      0);
    std::tie(stop, has_converged, at_floor, reason) = decision;
    // a SIGTERM or SIGINT: the run stops with what it finished
    if (Interruption::requested(qp.get_communicator()))
      {
        stop          = true;
        has_converged = false;
        reason        = "interrupted";
      }

    pcout << "  " << solver_name << ": it " << std::setw(3) << r.iteration
          << "  J = " << std::scientific << std::setprecision(6)
          << functional_unit * r.functional.total << "  |dx|_A/|dx_1|_A = " << std::setprecision(2)
          << r.correction / norm_x << "  rate = " << std::fixed
          << std::setprecision(3) << r.rate << "  active = " << r.active
          << std::endl;
    return stop || out_of_iterations;
  }


  bool
  Monitor::diverged() const
  {
    // Every step of the monotone solvers (projected Gauss-Seidel, the multigrid
    // cycles and their Newton steps) lowers J or leaves it, so a J that grows
    // by more than its round-off over an iteration means the solver's local
    // model is not the functional's; going on would hand the user an iterate
    // growing without bound (doc/performance.md, "Figures behind the code").
    // The active set method is no descent method and does not ask for the
    // check.
    if (!detect_divergence || history.size() < 2)
      return false;
    const double previous = history[history.size() - 2].functional.total,
                 current  = history.back().functional.total;
    // (an increase within J's round-off is none: where the matrix's
    // round-off reaches J, as on thin cells, the steps at the round-off
    // floor of the corrections move J up and down within it)
    return current > previous + std::max(divergence_tolerance * std::abs(previous),
                                          history.back().functional_round_off);
  }


  const IterationRecord &
  Monitor::record(const LevelVector &x, const LevelVector &x_old)
  {
    LevelVector d(x);
    d -= x_old;
    IterationRecord r;
    r.iteration    = history.size();
    const IterateMeasures measures = qp.measure(x, d);
    r.functional   = measures.functional;
    r.correction   = measures.correction;
    r.round_off    = measures.round_off;
    r.functional_round_off = measures.functional_round_off;
    std::vector<bool> active = qp.active_set(x);
    r.active       = qp.n_active(active);
    r.violation    = qp.max_violation(x);
    r.wall_seconds = timer.wall_time();
    const double previous = history.back().correction;
    r.rate = (history.size() > 1 && previous > 0) ? r.correction / previous : 0.;

    // Iterates never silently become NaN: stop the run with a message.
    AssertThrow(std::isfinite(r.functional.total) && std::isfinite(r.correction),
                ExcMessage(solver_name + ": the iterate became NaN/Inf at "
                           "iteration " + std::to_string(r.iteration) +
                           " (the data are finite, checked at the start: the functional "
                           "is likely too badly conditioned for double precision with "
                           "these 'Functional weights')"));
    history.push_back(r);
    // (the active set changed if it changed on any process)
    if (Utilities::MPI::max(active != active_set ? 1u : 0u, qp.get_communicator()) == 1)
      {
        active_set_changed_at = r.iteration;
        active_set.swap(active);
      }
    if (history.size() == 2)
      cycles_after_first = n_cycles;
    return history.back();
  }


  bool
  Monitor::at_round_off_floor(const double rho, const double factor)
  {
    at_floor = rules.at_round_off_floor(
      history, history.back().round_off, rho, factor, floor_stagnated);
    return at_floor;
  }


  unsigned int
  Monitor::last_measured_iteration() const
  {
    // stop before the round-off floor distorts the measure
    unsigned int last = history.size() - 1;
    while (last > 2 && history[last].correction <= 10. * history[last].round_off)
      --last;
    if (floor_stagnated)
      last = std::max(2u, last - 4);
    return last;
  }


  double
  Monitor::rate_per_cycle() const
  {
    if (history.size() < 3 || n_cycles <= cycles_after_first ||
        history[1].correction <= 0)
      return 0.;
    const unsigned int last      = last_measured_iteration();
    const double       reduction = history[last].correction / history[1].correction;
    const double       per_iteration_cycles =
      double(n_cycles - cycles_after_first) / (history.size() - 2);
    return std::pow(reduction, 1. / (per_iteration_cycles * (last - 1)));
  }


  std::pair<double, unsigned int>
  Monitor::measured_reduction() const
  {
    if (history.size() < 3 || history[1].correction <= 0)
      return {0., 0u};
    const unsigned int last = last_measured_iteration();
    // (a run that starts at its floor, as a late Tresca problem of the
    // Coulomb fixed point may, has nothing to measure)
    if (history[last].correction <= 10. * history[last].round_off)
      return {0., 0u};
    return {std::log(history[last].correction / history[1].correction), last - 1};
  }


  double
  Monitor::linear_rate() const
  {
    // (a correction near its round-off floor has a rate that is noise)
    double rho = 0.;
    for (unsigned int k = std::max(active_set_changed_at + 1, 2u); k < history.size(); ++k)
      if (history[k].correction > 1000. * history[k].round_off)
        rho = std::max(rho, history[k].rate);
    return rho;
  }


  double
  Monitor::asymptotic_rate() const
  {
    // the first iterations (nonlinear phase, paper section 7) are left out
    const unsigned int n     = history.size();
    const unsigned int first = std::max(2u, n > 5 ? n - 5 : 2u);
    double             log_sum = 0;
    unsigned int       count   = 0;
    for (unsigned int k = first; k < n; ++k)
      if (history[k].rate > 0)
        {
          log_sum += std::log(history[k].rate);
          ++count;
        }
    return count > 0 ? std::exp(log_sum / count) : 0.;
  }


  std::string
  Monitor::csv() const
  {
    std::ostringstream out;
    out << "iteration,functional,functional_eq,functional_const,"
           "functional_compl,correction,rate,active,violation,wall_seconds\n";
    out << std::setprecision(12);
    const double u = functional_unit;
    for (const auto &r : history)
      out << r.iteration << ',' << u * r.functional.total << ',' << u * r.functional.eq
          << ',' << u * r.functional.constitutive << ','
          << u * r.functional.complementarity << ',' << std::sqrt(u) * r.correction << ','
          << r.rate << ',' << r.active << ',' << r.violation << ','
          << r.wall_seconds << '\n';
    return out.str();
  }


  std::string
  Monitor::why_not_converged() const
  {
    if (converged())
      return "";
    std::ostringstream why;
    if (!not_converged_why.empty())
      why << "not converged: " << not_converged_why;
    else if (reason == "stalled")
      why << "not converged: stalled at a rate of " << std::fixed << std::setprecision(4)
          << asymptotic_rate() << " per iteration"
          << (parameters.krylov_steps == 0 ?
                " (the default solver, Solver/Krylov steps > 0, converges there)" :
                "");
    else if (reason == "diverged")
      why << "not converged: J increased in iteration " << history.size() - 1 << " from "
          << std::scientific << std::setprecision(3)
          << functional_unit * history[history.size() - 2].functional.total << " to "
          << functional_unit * history.back().functional.total
          << ", which a monotone solver's step cannot do: its multilevel model of the "
             "functional is wrong on this mesh ('Solver/Type' = active set solves the "
             "problem directly)";
    else
      why << "not converged within 'Solver/Max iterations' = " << parameters.max_iterations;
    return why.str();
  }
} // namespace FoslsContact
