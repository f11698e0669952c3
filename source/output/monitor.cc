#include <fosls_contact/output/monitor.h>

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
    const double norm_x = std::max(history[1].correction, 1e-300);
    // Both the round-off floor and the tolerance take the rate into
    // account: at a rate rho the error is about rho/(1-rho) times the
    // correction, so where rho > 1/2 that multiple of the correction is
    // compared (rho: the larger of the last two rates, so that one lucky
    // step does not end a slow run). A plain W-cycle creeping at 0.992
    // (the square with contact at one end, gap 0.02 (1 - x), 6 levels,
    // zero start, Krylov steps = 0) stops after 2010 iterations, the force
    // 2.8e-7 off the active set solver's; comparing the correction alone
    // stopped it after 1376 iterations, 3.4e-5 off.
    // (history[0] is the start, whose rate is 0)
    const double rho    = std::max(r.rate, history[history.size() - 2].rate);
    const double factor = rho < 1. ? std::max(1., rho / (1. - rho)) :
                                     std::numeric_limits<double>::infinity();
    bool stop = at_round_off_floor(x, rho, factor);
    if (parameters.stopping == Parameters::Solver::Stopping::tolerance)
      stop |= r.correction * factor <= parameters.tolerance * norm_x;
    else
      stop |= at_discretization_accuracy();
    has_converged = stop;
    reason        = !stop                                                             ? "" :
                    at_floor                                                          ? "round-off floor" :
                    parameters.stopping == Parameters::Solver::Stopping::tolerance ? "tolerance" :
                                                                                     "discretization accuracy";
    if (!stop && detect_stalls && detect_stall())
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
    // Every step of the monotone solvers (projected Gauss-Seidel, the
    // multigrid cycles and their Newton steps) lowers J or leaves it, so a
    // J that grows by more than its evaluation error over an iteration
    // means the solver's local model is not the functional's; going on
    // would hand the user an iterate growing without bound (measured: J
    // 3.5e-6, 2.8e31, 6.6e81). The active set method is no descent method
    // and does not ask for the check.
    if (!detect_divergence || history.size() < 2)
      return false;
    const double previous = history[history.size() - 2].functional.total,
                 current  = history.back().functional.total;
    return current > previous + divergence_tolerance * std::abs(previous);
  }


  const IterationRecord &
  Monitor::record(const LevelVector &x, const LevelVector &x_old)
  {
    LevelVector d(x);
    d -= x_old;
    IterationRecord r;
    r.iteration    = history.size();
    r.functional   = qp.parts(x);
    r.correction   = qp.energy_norm(d);
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
  Monitor::at_round_off_floor(const LevelVector &x, const double rho, const double factor)
  {
    // A correction within a factor 10 of the round-off level of the
    // corrections at x (ConstrainedQP::round_off_correction) carries no
    // information about the error, whatever the tolerance asks for. This
    // also ends a run whose start is already exact (its first correction
    // is round-off). A rate of 1 or more near the floor is its noise.
    IterationRecord &r     = history.back();
    const double     floor = qp.round_off_correction(x);
    r.round_off            = floor;
    bool stop = r.correction <= 10. * floor && (rho >= 1. || r.correction * factor <= 10. * floor);
    // Should the estimate be low for some mesh, the corrections stagnate
    // above it: four iterations in a row without a new smallest correction,
    // all within 1000 times the estimate, is the floor as well. (A slow
    // steady decrease must not be taken for it: one of the four must have
    // gone up, rate >= 1. Without that condition the creep at 0.992 above
    // stopped here after 1473 iterations, the force 1.6e-5 off.)
    if (!stop && history.size() > 8)
      {
        double smallest_before = std::numeric_limits<double>::max();
        for (unsigned int k = 1; k + 4 < history.size(); ++k)
          smallest_before = std::min(smallest_before, history[k].correction);
        bool stagnating = true, went_up = false;
        for (unsigned int k = history.size() - 4; stagnating && k < history.size(); ++k)
          {
            stagnating = history[k].correction >= 0.5 * smallest_before &&
                         history[k].correction <= 1000. * floor;
            went_up |= history[k].rate >= 1.;
          }
        stagnating &= went_up;
        stop            = stagnating;
        floor_stagnated = stagnating;
      }
    at_floor = stop;
    return stop;
  }


  bool
  Monitor::at_discretization_accuracy() const
  {
    // J(x) - J(x*) = 1/2 |x - x*|_A^2 (on the final active set) and the
    // algebraic error is about |d|_A rho/(1-rho); J(x) itself estimates the
    // squared discretization error. The estimate holds only in the linear
    // phase (paper section 7, phase III): the active set must not have
    // changed in the last iteration, and rho is the largest rate since it
    // last changed. (On the half disc with 4 levels, with the mean rate of
    // the nonlinear phase the run stopped after 2 iterations at 10 times
    // the converged J.) (rho is not capped below 1: with a cap of 0.95 a
    // method slower than that would stop too early; projected Gauss-Seidel,
    // whose rate is not steady, is refused this criterion, see
    // Parameters::Solver)
    const IterationRecord &r   = history.back();
    double                 rho = 0.;
    for (unsigned int k = active_set_changed_at + 1; k < history.size(); ++k)
      rho = std::max(rho, history[k].rate);
    rho                    = std::max(rho, 0.05);
    const double algebraic = r.correction * rho / (1. - rho) / std::sqrt(2.);
    return history.size() > 2 && active_set_changed_at < r.iteration && rho < 1. &&
           algebraic <=
             parameters.discretization_fraction * std::sqrt(std::max(r.functional.total, 0.));
  }


  bool
  Monitor::detect_stall()
  {
    // The last stall_window iterations, with the active set unchanged (the
    // linear phase: the rate is that of the method on a fixed truncation,
    // and will not improve by itself)
    const unsigned int k = history.size() - 1;
    if (k < stall_window + 1 || active_set_changed_at + stall_window > k)
      return false;
    // every rate between stall_rate and 1/stall_rate (a steady rate: a
    // correction that grows, as before an active set changes, is not a
    // stall), the corrections far above their round-off floor (where the
    // rate is noise)
    double log_rate = 0;
    for (unsigned int j = k + 1 - stall_window; j <= k; ++j)
      {
        if (history[j].rate < stall_rate || history[j].rate > 1. / stall_rate ||
            history[j].correction <= 1000. * history[j].round_off)
          return false;
        log_rate += std::log(history[j].rate) / stall_window;
      }
    // the estimated error (rho / (1 - rho) times the correction) against
    // the stopping rule's target, at the mean rate rho of the window
    const double rho = std::exp(log_rate);
    double       error = std::numeric_limits<double>::infinity(), target;
    if (parameters.stopping == Parameters::Solver::Stopping::tolerance)
      {
        if (rho < 1.)
          error = history[k].correction * rho / (1. - rho);
        target = parameters.tolerance * history[1].correction;
      }
    else
      {
        if (rho < 1.)
          error = history[k].correction * rho / (1. - rho) / std::sqrt(2.);
        target = parameters.discretization_fraction *
                 std::sqrt(std::max(history[k].functional.total, 0.));
      }
    if (!(error > target))
      return false;
    // the iterations that would take, against those left
    const double needed =
      rho < 1. ? std::log(error / target) / -std::log(rho) : std::numeric_limits<double>::infinity();
    if (needed <= stall_excess * (double(parameters.max_iterations) - k))
      return false;
    stall_error = target > 0 ? error / target : std::numeric_limits<double>::infinity();
    return true;
  }


  double
  Monitor::rate_per_cycle() const
  {
    if (history.size() < 3 || n_cycles <= cycles_after_first ||
        history[1].correction <= 0)
      return 0.;
    // stop before the round-off floor distorts the measure
    unsigned int last = history.size() - 1;
    while (last > 2 && history[last].correction <= 10. * history[last].round_off)
      --last;
    if (floor_stagnated)
      last = std::max(2u, last - 4);
    const double reduction = history[last].correction / history[1].correction;
    const double per_iteration_cycles =
      double(n_cycles - cycles_after_first) / (history.size() - 2);
    return std::pow(reduction, 1. / (per_iteration_cycles * (last - 1)));
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
} // namespace FoslsContact
