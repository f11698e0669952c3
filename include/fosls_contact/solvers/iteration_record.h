#ifndef fosls_contact_solvers_iteration_record_h
#define fosls_contact_solvers_iteration_record_h

#include <fosls_contact/qp/constrained_qp.h>

namespace FoslsContact
{
  /** What is recorded after each iteration of any solver. */
  struct IterationRecord
  {
    unsigned int    iteration = 0;
    FunctionalValue functional;
    double          correction    = 0; ///< energy norm of x_k - x_{k-1}
    double          rate          = 0; ///< correction_k / correction_{k-1}
    unsigned int    active        = 0;
    double          violation     = 0;
    double          round_off     = 0; ///< ConstrainedQP::round_off_correction
    double          functional_round_off = 0; ///< IterateMeasures::functional_round_off
    double          wall_seconds  = 0;
  };
} // namespace FoslsContact

#endif
