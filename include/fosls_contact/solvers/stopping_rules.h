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
   * on measured behaviour of the solvers (the comments give the figures);
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
     * active set last changed at iteration @p active_set_changed_at.
     */
    bool at_discretization_accuracy(const std::vector<IterationRecord> &history,
                                    const unsigned int active_set_changed_at) const;
    /**
     * The stall test of Monitor::enable_stall_detection() on @p history;
     * for a stall, @p error_ratio is the estimated error over the stopping
     * rule's target.
     */
    bool stalled(const std::vector<IterationRecord> &history,
                 const unsigned int                  active_set_changed_at,
                 double &                            error_ratio) const;

  private:
    /**
     * The stall test's constants. The plain cycle where the contact zone
     * ends inside coarse faces creeps at 0.996 to 1.000 per iteration
     * with the active set settled (half disc, 3 levels; the square
     * [-1,1] x [0,1] with the gap 0.02 - 0.015 x^2, 5 levels), its
     * estimated error 1e6 to 3e7 times the tolerance's target, and is found from
     * iteration 12 to 15 on. The slowest converging runs of the tests keep
     * a margin: the plain cycle creeping at 0.997 on the square with
     * contact at one end (mg_round_off_stop, 1368 iterations allowed
     * 3000) would need 2.5 times the iterations left, and every other
     * multigrid run of the tests has no 5 steady rates above 0.99 in the
     * linear phase.
     */
    static constexpr unsigned int stall_window = 5;
    static constexpr double       stall_rate   = 0.99;
    static constexpr double       stall_excess = 10.;

    const Parameters::Solver parameters;
  };
} // namespace FoslsContact

#endif
