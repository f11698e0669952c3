#ifndef fosls_contact_problem_problem_checks_h
#define fosls_contact_problem_problem_checks_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/scene.h>

namespace FoslsContact
{
  /**
   * The checks between the assembly and the solve: of the assembled
   * problem, not of the input file's syntax (ParameterReader does that).
   * Each refuses, with one line naming the input to change, a problem that
   * the solvers would otherwise meet as NaN iterates, a singular coarse
   * matrix or a functional that is not convex.
   */
  template <int dim>
  class ProblemChecks
  {
  public:
    ProblemChecks(const Parameters::AllParameters &parameters,
                  const Scene<dim> &               scene,
                  const Discretization<dim> &      discretization,
                  const ConstrainedQP &            qp,
                  const ConditionalOStream &       pcout);

    /** Refuse data (Dirichlet values, traction, gap, body force) that are not finite. */
    void check_data() const;
    /**
     * Refuse boundary conditions that leave a rigid motion free: the
     * functional is then only semidefinite, the coarsest level singular
     * and the iterates drift along the motion.
     */
    void check_rigid_motions() const;
    /**
     * Refuse functional weights that make the problem indefinite (paper
     * eq. 10), checked on the finest level with at most Solver/Definiteness
     * check max dofs DoFs, in the section "Definiteness check" of @p timer.
     * Returns the wall seconds it took (0 if skipped).
     */
    double check_definiteness(TimerOutput &timer) const;

  private:
    const Parameters::AllParameters &parameters;
    const Scene<dim> &               scene;
    const Discretization<dim> &      discretization;
    const ConstrainedQP &            qp;
    const ConditionalOStream &       pcout;
  };
} // namespace FoslsContact

#endif
