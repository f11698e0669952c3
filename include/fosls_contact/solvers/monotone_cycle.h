#ifndef fosls_contact_solvers_monotone_cycle_h
#define fosls_contact_solvers_monotone_cycle_h

#include <deal.II/lac/sparse_matrix.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/solvers/coarse_solver.h>
#include <fosls_contact/solvers/level_operators.h>
#include <fosls_contact/solvers/level_truncation.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>
#include <fosls_contact/solvers/patch_smoother.h>
#include <fosls_contact/solvers/solver_statistics.h>

#include <optional>
#include <utility>
#include <vector>

namespace FoslsContact
{
  /**
   * One cycle of the monotone multilevel method (paper sections 4.2, 5
   * and 6) on level l: it minimizes the level functional
   * Q_l(v) = 1/2 v^T A_l v - r_l^T v over v <= ub_l by
   *  1. the forward sweeps of the patch smoother (pre-smoothing),
   *  2. gamma times (V: 1, W: 2; F: an F-cycle, then a V-cycle on the
   *     coarser level) a coarse correction: the truncated prolongation P~
   *     drops the fine DoFs that are fixed or active (eq. 34), the coarse
   *     operator is its Galerkin product (LevelOperators), the coarse
   *     obstacle is the projection of the fine defect obstacle (eqs. 31-32,
   *     35-36, CoarseObstacles), and the coarse problem is solved by one
   *     cycle on level l - 1,
   *  3. the backward sweeps (post-smoothing);
   * on level 0 the box-constrained problem is solved exactly
   * (CoarseSolver).
   *
   * The linear cycle, the Newton step's preconditioner (NewtonStep), is the
   * same cycle with infinite obstacles and the roles of the Newton step's
   * linear problem on the finest level (PatchSmoother::set_linear_roles());
   * it removes coarse faces with a truncated son instead of rerouting
   * their flux (FluxRerouting), and it stops at linear_coarsest(), which it
   * solves exactly.
   *
   * Every coarse correction minimizes the fine functional (the Galerkin
   * operators), so J never increases; this is checked for every correction
   * from its own terms and counted (MultigridCounters::energy_increases).
   * Should a coarse correction leave the fine feasible set (only possible
   * when the obstacle normals differ between neighbouring vertices), it is
   * shortened to the feasible part, which by convexity along the line
   * still decreases J (MultigridCounters::feasibility_dampings).
   */
  template <int dim>
  class MonotoneCycle
  {
  public:
    /**
     * The cycle of @p parameters on @p hierarchy, smoothing with
     * @p pre_smoother and @p post_smoother (on the same patches), with the
     * coarse operators of @p operators and the exact solves of
     * @p coarse_solver; what it counts goes to @p counters.
     */
    MonotoneCycle(const MultilevelHierarchy<dim> &hierarchy,
                  const Parameters::Solver &      parameters,
                  PatchSmoother &                 pre_smoother,
                  const PatchSmoother &           post_smoother,
                  LevelOperators<dim> &           operators,
                  CoarseSolver &                  coarse_solver,
                  MultigridCounters &             counters);

    /**
     * One cycle on level @p l for Q_l with matrix @p A, right-hand side
     * @p r, obstacles @p ub and roles @p role; @p v is updated. With
     * @p linear, the linear cycle. @p type is the cycle on this level (the
     * parameter file's by default). Collective.
     */
    void run(const unsigned int          l,
             const SparseMatrix<double> &A,
             const LevelVector &         r,
             const LevelVector &         ub,
             const std::vector<DoFRole> &role,
             LevelVector &               v,
             const bool                  linear = false,
             std::optional<Parameters::Solver::Cycle> type = {});

    /**
     * The pair terms K that the linear cycle adds to A on the finest level
     * (nullptr: none), in its smoother (PatchSmoother::set_linear_roles())
     * and in the defect it restricts from there (PairTerms).
     */
    void set_linear_pair_terms(const PairTerms *terms) { linear_pair_terms = terms; }

    /** Set up the patch smoother of level @p l for @p A with @p role. */
    void initialize_smoother(const unsigned int          l,
                             const SparseMatrix<double> &A,
                             const std::vector<DoFRole> &role);

    /**
     * Whether the cycle (the linear one if @p linear) solves level @p l
     * exactly instead of smoothing it and visiting the levels below.
     */
    bool solved_exactly(const unsigned int l, const bool linear) const
    {
      return l == 0 || (linear && l == linear_coarsest_level);
    }

    /**
     * The linear cycle solves the finest level below the finest with at
     * most this many DoFs exactly, in one visit, instead of visiting the
     * levels below it. Its problem is linear (the obstacles of the linear
     * cycle are +inf) and its operator changes only with the roles of a
     * Newton step (on the square: once per solve), so its dense factor is
     * computed that often, and a visit costs two triangular solves: on the
     * square's level 2 (130 DoFs) half of a W-cycle visit with the levels
     * below it (doc/performance.md, section 3). Level 3 (450 DoFs) is too
     * large for it: its dense factor costs more than the cycles it saves
     * (doc/performance.md, "Figures behind the code"). In 3D level 2 has 1095 DoFs and level 1 189.
     */
    static constexpr unsigned int linear_coarse_max_dofs = 200;

  private:
    /**
     * The work vectors of the cycle on one level (l: fine, l - 1: coarse);
     * a level is never visited twice at once, and allocating them per
     * visit showed up as page faults.
     */
    struct Scratch
    {
      LevelTruncation truncation;
      LevelVector     residual, w;
      LevelVector     r_coarse, ub_coarse, c, Ac;
    };

    /** The sweeps of @p smoother on level @p l (obstacles @p ub). */
    void smooth(const unsigned int   l,
                const PatchSmoother &smoother,
                const LevelVector &  ub,
                const LevelVector &  r,
                LevelVector &        v,
                const bool           linear);
    /**
     * The scratch of level @p l for the operator @p A and the roles
     * @p role: the vectors and the part of the truncation that does not
     * depend on the iterate.
     */
    void prepare(const unsigned int          l,
                 const SparseMatrix<double> &A,
                 const std::vector<DoFRole> &role);
    /**
     * Rebuild the operator of level l - 1 (and its patch smoother) for the
     * truncation of level @p l in its scratch, if it changed; returns
     * whether it did. Collective.
     */
    bool update_operator(const unsigned int          l,
                         const SparseMatrix<double> &A,
                         const std::vector<DoFRole> &role,
                         const bool                  linear);
    /**
     * Visit @p visit of level l - 1 from level @p l: the truncated
     * operators, the coarse defect and obstacle, the coarse cycle and the
     * correction of @p v. @p alpha: the damping of the last visit's
     * correction in, this one's out.
     */
    void coarse_correction(const unsigned int          l,
                           const SparseMatrix<double> &A,
                           const LevelVector &         r,
                           const LevelVector &         ub,
                           const std::vector<DoFRole> &role,
                           LevelVector &               v,
                           const bool                  linear,
                           const Parameters::Solver::Cycle type,
                           const unsigned int          visit,
                           double &                    alpha);
    /**
     * v += alpha P~ c, with alpha <= 1 the largest step that keeps v
     * feasible (1 when K_H is inside K_h); the change of Q_l is checked.
     * Returns alpha. Collective.
     */
    double correct(const unsigned int l, const LevelVector &ub, LevelVector &v);
    /**
     * The check of Solver/Check coarse defects: @p r_coarse, the coarse
     * defect that the second visit took from the first, against P~^T (r -
     * A v) recomputed (LevelOperators::coarse_defect_difference()).
     */
    void check_coarse_defect(const unsigned int          l,
                             const SparseMatrix<double> &A,
                             const LevelVector &         r,
                             const LevelVector &         v,
                             const LevelVector &         r_coarse);

    const MultilevelHierarchy<dim> &hierarchy;
    const Parameters::Solver &      parameters;
    PatchSmoother &                 pre_smoother;
    const PatchSmoother &           post_smoother;
    LevelOperators<dim> &           operators;
    CoarseSolver &                  coarse_solver;
    MultigridCounters &             counters;
    const unsigned int              finest;
    unsigned int                    linear_coarsest_level = 0;
    const PairTerms *               linear_pair_terms     = nullptr;
    std::vector<Scratch>            scratch;
  };
} // namespace FoslsContact

#endif
