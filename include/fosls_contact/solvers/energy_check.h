#ifndef fosls_contact_solvers_energy_check_h
#define fosls_contact_solvers_energy_check_h

namespace FoslsContact
{
  /**
   * The relative round-off a change of J may carry: a change computed
   * from its own terms (a patch step, a coarse correction, a coordinate
   * step) is exact up to a few units of the precision times the size of
   * those terms. Evaluating J itself would compare numbers with far larger
   * cancellation errors.
   */
  constexpr double energy_round_off = 1e-10;

  /**
   * Whether a step that changed J by @p change, computed from terms of
   * size @p terms (the sum of their absolute values), increased J beyond
   * round-off: the monotonicity check of every solver step.
   */
  inline bool
  increases_energy(const double change, const double terms)
  {
    // (1e-300: a change of exactly 0 with terms of 0 is no increase)
    return change > energy_round_off * terms + 1e-300;
  }
} // namespace FoslsContact

#endif
