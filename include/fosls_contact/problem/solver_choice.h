#ifndef fosls_contact_problem_solver_choice_h
#define fosls_contact_problem_solver_choice_h

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/qp_solver.h>

#include <memory>
#include <string>

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

    /**
     * A one-line warning that Solver/Type = active set will take long on
     * @p n_dofs DoFs, or "". Its sparse direct solves grow much faster than
     * the DoFs (the fill-in of the factors), like N^1.7 in 2D and N^2.4 in
     * 3D on the square and the cube, the more so in 3D, and the solve says
     * nothing before it ends: the cube's level 5 takes many minutes. The
     * warning comes above warning_dofs(), where an iteration takes about
     * 10 s, with the time per iteration that the two runs per dimension it
     * rests on predict (doc/performance.md, "Figures behind the code").
     */
    static std::string active_set_warning(const Parameters::Solver::Type type,
                                          const types::global_dof_index  n_dofs);

    /** The DoFs above which active_set_warning() warns: 2D 75,000, 3D 9,000. */
    static constexpr types::global_dof_index warning_dofs = dim == 2 ? 75000 : 9000;

    /** A solver for @p level_qp, the problem assembled on level @p level. */
    static std::unique_ptr<QPSolver> make(const Parameters::Solver &  parameters,
                                          const Discretization<dim> &discretization,
                                          const LevelTransfer<dim> & transfer,
                                          const ConstrainedQP &      level_qp,
                                          const unsigned int         level);
  };
} // namespace FoslsContact

#endif
