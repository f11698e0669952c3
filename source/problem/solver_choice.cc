#include <fosls_contact/problem/solver_choice.h>
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/monotone_multigrid.h>
#include <fosls_contact/solvers/projected_gauss_seidel.h>

#include <cmath>
#include <iomanip>
#include <sstream>

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
  std::string
  SolverChoice<dim>::active_set_warning(const Parameters::Solver::Type type,
                                        const types::global_dof_index  n_dofs)
  {
    if (type != Parameters::Solver::Type::active_set || n_dofs <= warning_dofs)
      return "";
    // seconds per iteration, N^p through the larger of the two runs the
    // estimate rests on (doc/performance.md, "Figures behind the code")
    const double reference_dofs    = dim == 2 ? 99330 : 7371;
    const double reference_seconds = dim == 2 ? 31.6 / 2 : 12.9 / 2;
    const double power             = dim == 2 ? 1.7 : 2.4;
    const double seconds = reference_seconds * std::pow(n_dofs / reference_dofs, power);
    std::ostringstream text;
    text << "Warning: Solver/Type = active set on " << n_dofs << " DoFs in " << dim
         << "D: its sparse direct solves grow like N^" << power << ", about "
         << std::fixed << std::setprecision(0) << seconds
         << " s per iteration here (from measurements on 2 busy cores), and nothing on the "
            "screen before the solve ends; the default, monotone multigrid, costs about linearly in N";
    return text.str();
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
