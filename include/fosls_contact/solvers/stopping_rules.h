#ifndef fosls_contact_solvers_stopping_rules_h
#define fosls_contact_solvers_stopping_rules_h

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/solvers/iteration_record.h>

#include <vector>

namespace FoslsContact
{
  /**
   * The tests on a run's history that end it besides the tolerance: the
   * round-off floor of the corrections, the discretization accuracy
   * (paper section 7) and the stall of a slowly creeping cycle. Each rests
   * on the observed behaviour of the solvers (doc/performance.md, "Figures behind the code");
   * they are kept apart from the Monitor that records, prints and
   * decides, so that each rule can be read whole.
   */
  class StoppingRules
  {
  public:
    explicit StoppingRules(const Parameters::Solver &parameters);

    /**
     * Whether the last correction of @p history is at the round-off floor
     * @p floor of the corrections (ConstrainedQP::round_off_correction()),
     * with the rate @p rho and the error factor @p factor = max(1, rho/(1 -
     * rho)), or the corrections stagnate above it (@p stagnated).
     */
    bool at_round_off_floor(const std::vector<IterationRecord> &history,
                            const double                        floor,
                            const double                        rho,
                            const double                        factor,
                            bool &                              stagnated) const;
    /**
     * The stopping criterion "discretization accuracy" on @p history, whose
     * active set last changed at iteration @p active_set_changed_at, with
     * a rate of at least @p rate_floor (Monitor::set_rate_floor()) and at
     * least @p minimum_rates rates measured in the linear phase
     * (Monitor::require_rates()).
     */
    bool at_discretization_accuracy(const std::vector<IterationRecord> &history,
                                    const unsigned int active_set_changed_at,
                                    const double       rate_floor    = 0.,
                                    const unsigned int minimum_rates = 1) const;
    /**
     * The stall test of Monitor::enable_stall_detection() on @p history,
     * the tolerance relative to @p first_correction
     * (Monitor::tolerance_reference()); for a stall, @p error_ratio is the
     * estimated error over the stopping rule's target.
     */
    bool stalled(const std::vector<IterationRecord> &history,
                 const unsigned int                  active_set_changed_at,
                 const double                        first_correction,
                 double &                            error_ratio) const;

  private:
    /**
     * The stall test's constants. The plain cycle where the contact zone
     * ends inside coarse faces creeps at a rate of almost 1 per iteration
     * with the active set settled, its estimated error orders of magnitude
     * above the target; the window finds it soon after the active set
     * settles. The slowest converging runs of the tests keep a margin: the
     * slowest would still need more than twice the iterations left, and no
     * other multigrid run of the tests has stall_window steady rates above
     * stall_rate in the linear phase (doc/performance.md, "Figures behind the code").
     */
    static constexpr unsigned int stall_window = 5;
    static constexpr double       stall_rate   = 0.99;
    static constexpr double       stall_excess = 10.;

    const Parameters::Solver parameters;
  };
} // namespace FoslsContact

#endif
