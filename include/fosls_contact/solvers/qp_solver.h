#ifndef fosls_contact_solvers_qp_solver_h
#define fosls_contact_solvers_qp_solver_h

#include <fosls_contact/output/monitor.h>
#include <fosls_contact/qp/constrained_qp.h>

#include <map>
#include <string>

namespace FoslsContact
{
  /**
   * Interface of the solvers for a ConstrainedQP. @p x enters as the
   * starting guess (it is projected to the feasible set first) and leaves
   * as the solution; every iteration is reported to @p monitor.
   */
  class QPSolver
  {
  public:
    virtual ~QPSolver() = default;
    virtual void solve(const ConstrainedQP &qp,
                       LevelVector &        x,
                       Monitor &            monitor) = 0;

    /** Wall time and number of calls of one part of solve(). */
    struct SectionTime
    {
      double       seconds = 0;
      unsigned int calls   = 0;
    };
    /** The wall time of the parts of solve() so far, by name (none here). */
    virtual std::map<std::string, SectionTime> section_times() const { return {}; }
  };
} // namespace FoslsContact

#endif
