#include <fosls_contact/solvers/stopping_rules.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace FoslsContact
{
  StoppingRules::StoppingRules(const Parameters::Solver &parameters)
    : parameters(parameters)
  {}


  bool
  StoppingRules::at_round_off_floor(const std::vector<IterationRecord> &history,
                                    const double                        floor,
                                    const double                        rho,
                                    const double                        factor,
                                    bool &                              stagnated) const
  {
    // A correction within a factor 10 of the round-off level of the
    // corrections at x (ConstrainedQP::round_off_correction) carries no
    // information about the error, whatever the tolerance asks for. This
    // also ends a run whose start is already exact (its first correction
    // is round-off). A rate of 1 or more near the floor is its noise.
    const IterationRecord &r = history.back();
    bool stop = r.correction <= 10. * floor && (rho >= 1. || r.correction * factor <= 10. * floor);
    // Should the estimate be low for some mesh, the corrections stagnate
    // above it: four iterations in a row without a new smallest correction,
    // all within 1000 times the estimate, is the floor as well. (A slow
    // steady decrease must not be taken for it: one of the four must have
    // gone up, rate >= 1; without that condition the creep of the
    // Monitor's example stopped here with the force far off.)
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
        stop      = stagnating;
        stagnated = stagnating;
      }
    return stop;
  }


  bool
  StoppingRules::at_discretization_accuracy(const std::vector<IterationRecord> &history,
                                            const unsigned int active_set_changed_at,
                                            const double       rate_floor,
                                            const unsigned int minimum_rates) const
  {
    // J(x) - J(x*) = 1/2 |x - x*|_A^2 (on the final active set) and the
    // algebraic error is about |d|_A rho/(1-rho); J(x) itself estimates the
    // squared discretization error. The estimate holds only in the linear
    // phase (paper section 7, phase III): the active set must not have
    // changed in the last iteration, and rho is the largest rate since it
    // last changed. (With the mean rate of the nonlinear phase a run
    // stopped long before J had converged: doc/performance.md, "Figures
    // behind the code".) (rho is not capped below 1: with a cap of 0.95 a
    // method slower than that would stop too early; projected Gauss-Seidel,
    // whose rate is not steady, is refused this criterion, see
    // Parameters::Solver)
    // The rate of a run that starts next to its solution can be far below
    // the method's: a level of nested iteration may see a small second
    // correction after a large first one while the slow modes of the
    // contact zone have barely moved. Such a level takes at least the rate
    // its coarser levels measured (rate_floor: the multigrid's rate depends
    // little on the level), and those levels measure two rates before they
    // trust them (minimum_rates; doc/method.md section 7.5).
    const IterationRecord &r   = history.back();
    double                 rho = 0.;
    for (unsigned int k = active_set_changed_at + 1; k < history.size(); ++k)
      rho = std::max(rho, history[k].rate);
    rho                    = std::max({rho, 0.05, rate_floor});
    const double algebraic = r.correction * rho / (1. - rho) / std::sqrt(2.);
    // (the rates of the linear phase: those after the first iteration and
    // after the active set's last change)
    const unsigned int rates =
      r.iteration - std::min(r.iteration, std::max(active_set_changed_at, 1u));
    return rates >= std::max(minimum_rates, 1u) && rho < 1. &&
           algebraic <=
             parameters.discretization_fraction * std::sqrt(std::max(r.functional.total, 0.));
  }


  bool
  StoppingRules::stalled(const std::vector<IterationRecord> &history,
                         const unsigned int                  active_set_changed_at,
                         const double                        first_correction,
                         double &                            error_ratio) const
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
        target = parameters.tolerance * first_correction;
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
    error_ratio = target > 0 ? error / target : std::numeric_limits<double>::infinity();
    return true;
  }
} // namespace FoslsContact
