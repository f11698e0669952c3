#include <fosls_contact/problem/solver_choice.h>
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/monotone_multigrid.h>
#include <fosls_contact/solvers/projected_gauss_seidel.h>

namespace FoslsContact
{
  template <int dim>
  const char *
  SolverChoice<dim>::name(const Parameters::Solver::Type type)
  {
    switch (type)
      {
        case Parameters::Solver::Type::monotone_multigrid:
          return "monotone multigrid";
        case Parameters::Solver::Type::active_set:
          return "active set";
        default:
          return "projected gauss seidel";
      }
  }


  template <int dim>
  std::unique_ptr<QPSolver>
  SolverChoice<dim>::make(const Parameters::Solver &  parameters,
                          const Discretization<dim> &discretization,
                          const LevelTransfer<dim> & transfer,
                          const ConstrainedQP &      level_qp,
                          const unsigned int         level)
  {
    switch (parameters.type)
      {
        case Parameters::Solver::Type::active_set:
          return std::make_unique<ActiveSetDirect>();
        case Parameters::Solver::Type::projected_gauss_seidel:
          return std::make_unique<ProjectedGaussSeidel>(discretization.sweep_order(level));
        default:
          {
            return std::make_unique<MonotoneMultigrid<dim>>(
              discretization, transfer, level, level_qp.sparsity, parameters);
          }
      }
  }


  template struct SolverChoice<2>;
  template struct SolverChoice<3>;
} // namespace FoslsContact
