#ifndef fosls_contact_solvers_projected_gauss_seidel_h
#define fosls_contact_solvers_projected_gauss_seidel_h

#include <fosls_contact/solvers/qp_solver.h>

namespace FoslsContact
{
  /**
   * Projected Gauss-Seidel (coordinate descent with projection): the
   * classic baseline whose rate deteriorates as h -> 0 (paper section 4.2).
   * Each coordinate step minimizes J exactly along e_i within the bounds,
   * so J never increases.
   */
  class ProjectedGaussSeidel : public QPSolver
  {
  public:
    void solve(const ConstrainedQP &qp,
               LevelVector &        x,
               Monitor &            monitor) override;
  };
} // namespace FoslsContact

#endif
