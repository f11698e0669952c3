#ifndef fosls_contact_problem_solver_choice_h
#define fosls_contact_problem_solver_choice_h

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/qp_solver.h>

#include <memory>

namespace FoslsContact
{
  /**
   * The one place where Solver/Type becomes a solver: the run's solver and
   * those of the initial guess's level solves are made here, so that both
   * are the same method with the same parameters.
   */
  template <int dim>
  struct SolverChoice
  {
    /** The name of @p type in the input file, for the output. */
    static const char *name(const Parameters::Solver::Type type);

    /** A solver for @p level_qp, the problem assembled on level @p level. */
    static std::unique_ptr<QPSolver> make(const Parameters::Solver &  parameters,
                                          const Discretization<dim> &discretization,
                                          const LevelTransfer<dim> & transfer,
                                          const ConstrainedQP &      level_qp,
                                          const unsigned int         level);
  };
} // namespace FoslsContact

#endif
