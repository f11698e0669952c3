#ifndef fosls_contact_problem_problem_checks_h
#define fosls_contact_problem_problem_checks_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/qp/definiteness_check.h>
#include <fosls_contact/scene/scene.h>

#include <limits>
#include <set>
#include <string>

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

    /**
     * Refuse data (Dirichlet values, traction, gap, body force) that are
     * not finite, or too large or too small for double precision
     * (DataCheck).
     */
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
     *
     * A coarser level than the finest is checked with C_compl raised by
     * coarse_level_margin: the largest definite C_compl can only go down
     * under refinement (the spaces are nested), so passing there alone
     * would not mean passing on the finest level.
     *
     * @p passed (if given) holds the uniform levels that passed before in
     * this run (an adaptive run checks once per mesh): such a level is not
     * checked again, and one that passes now is added.
     */
    double check_definiteness(TimerOutput &timer, std::set<unsigned int> *passed = nullptr) const;

    /**
     * The weight C_compl = auto takes: Parameters::Weights::auto_compl_cap,
     * or Parameters::Weights::auto_compl_fraction of the largest definite
     * C_compl on the level check_definiteness() checks where that is less
     * (DefinitenessCheck::limit_factor of that level, assembled here on its
     * own, before the finest level is). The cap where the limit cannot be
     * computed: the checks that follow then name the cause. Where the check
     * made here is the one check_definiteness() would make, its level goes
     * into @p passed.
     */
    struct ComplWeight
    {
      double value;
      /** The largest definite C_compl on #level (+inf: none; NaN: not computed). */
      double limit = std::numeric_limits<double>::quiet_NaN();
      int    level = -1;
    };
    ComplWeight choose_compl_weight(TimerOutput &timer, std::set<unsigned int> &passed) const;

    /**
     * The level check_definiteness() factorizes when it runs: the finest
     * with at most @p solver's Definiteness check max dofs DoFs; -1 if
     * none has so few or the check is switched off (0).
     */
    static int definiteness_level(const Discretization<dim> &discretization,
                                  const Parameters::Solver & solver);

    /**
     * The relative margin on C_compl of a check on a coarser level than
     * the finest. bench/definiteness_limit.py bisects the largest definite
     * C_compl level by level: it goes down under refinement by a share that
     * shrinks from level to level by a steady factor (on the square about
     * 1/2, on the cube about 0.6), so the way down from a level is about
     * its last step times factor / (1 - factor): a few percent from the
     * square's level 6, about a third from the cube's level 4. The margin
     * covers both; the figures are in doc/method.md section 6.
     */
    static constexpr double coarse_level_margin = 0.5;
    /**
     * A relative eigenvalue of the contact Schur complement this close to
     * 0 is round-off (its entries are scaled to a unit diagonal), where
     * an indefinite C_compl gives eigenvalues of order -1e-3 to -0.1
     * (tests/solver/functional_weights).
     */
    static constexpr double round_off_eigenvalue = 1e-10;

  private:
    /**
     * Why no C_compl makes the contact Schur complement definite: the
     * pressure of an incompressible body with friction, or the
     * conditioning (Conditioning::advice()).
     */
    std::string singular_cause() const;

    /**
     * DefinitenessCheck::run() on @p level, on the first process, its
     * outcome on every process: on the assembled finest level if
     * @p use_assembled, else on @p level assembled here with @p weights.
     * Collective.
     */
    DefinitenessCheck check_level(const int                  level,
                                  const Parameters::Weights &weights,
                                  const bool                 use_assembled) const;
    /** "0.258 on level 6" (or "none", "unknown" for an infinite or NaN @p limit). */
    std::string limit_text(const double limit, const int level) const;

    const Parameters::AllParameters &parameters;
    const Scene<dim> &               scene;
    const Discretization<dim> &      discretization;
    const ConstrainedQP &            qp;
    const ConditionalOStream &       pcout;
  };
} // namespace FoslsContact

#endif
