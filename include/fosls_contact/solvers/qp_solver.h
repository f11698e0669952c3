#ifndef fosls_contact_solvers_qp_solver_h
#define fosls_contact_solvers_qp_solver_h

#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/iteration_observer.h>
#include <fosls_contact/solvers/solver_statistics.h>

namespace FoslsContact
{
  /**
   * Interface of the solvers for a ConstrainedQP. @p x enters as the
   * starting guess (it is projected to the feasible set first) and leaves
   * as the solution; every iteration is reported to @p observer, which
   * decides when to stop.
   */
  class QPSolver
  {
  public:
    virtual ~QPSolver() = default;
    virtual void solve(const ConstrainedQP &qp,
                       LevelVector &        x,
                       IterationObserver &  observer) = 0;

    /** The figures of the solves so far (none here). */
    virtual SolverStatistics statistics() const { return {}; }
  };
} // namespace FoslsContact

#endif
