#ifndef fosls_contact_solvers_monotone_multigrid_h
#define fosls_contact_solvers_monotone_multigrid_h
#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/solvers/qp_solver.h>
namespace FoslsContact
{
  template <int dim>
  class MonotoneMultigrid : public QPSolver
  {
  public:
    MonotoneMultigrid(const Discretization<dim> &, const LevelTransfer<dim> &,
                      const unsigned int, const Parameters::Solver &) {}
    void solve(const ConstrainedQP &, Vector<double> &, Monitor &) override
    { AssertThrow(false, ExcNotImplemented()); }
  };
}
#endif
