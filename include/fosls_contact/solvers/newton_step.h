#ifndef fosls_contact_solvers_newton_step_h
#define fosls_contact_solvers_newton_step_h

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/qp/tangential_pair.h>
#include <fosls_contact/solvers/monotone_cycle.h>
#include <fosls_contact/solvers/patch_smoother.h>
#include <fosls_contact/solvers/solver_statistics.h>

#include <limits>
#include <vector>

namespace FoslsContact
{
  /**
   * A 3D friction pair of owned DoFs (i, j) and a unit vector u of its
   * plane: the direction along which the Newton step's linear problem
   * moves it, or that of a curvature kappa u u^T it adds.
   */
  struct PairDirection
  {
    unsigned int            i, j;
    TangentialPair::Vector2 u;
    double                  kappa; ///< a curvature along u, or 0
  };

  /**
   * One step of truncated nonsmooth Newton multigrid with conjugate
   * gradients (Solver/Krylov steps > 0, the default solver):
   *  1. projected pre-smoothing on the finest level;
   *  2. the Newton direction on the inactive set of the result (a DoF at
   *     its bound whose multiplier (b - A x)_i is negative counts as
   *     inactive, so that the direction can release it): CG steps
   *     preconditioned by the linear truncated cycle (MonotoneCycle with
   *     linear = true), until the residual is cg_reduction times that of
   *     the first round (at most Krylov steps). A free DoF that the
   *     direction would push past its bound (only the early ones where
   *     it overshoots one: overshoot_fraction) is instead moved exactly to
   *     its bound and the linear problem solved again without it, as in a
   *     primal-dual active set step (at most max_rounds rounds). A round
   *     after the first starts CG from the last round's solution (zero at
   *     the DoFs now fixed): started from zero, a later round has to take
   *     its residual down from many orders of magnitude above the
   *     tolerance and can run out of its Krylov steps (doc/performance.md,
   *     "Figures behind the code");
   *  3. a line search that takes the best of the feasible steps along
   *     the direction (with 3D friction also along those of the first
   *     round and of the round before the last);
   *  4. projected post-smoothing.
   * J never increases.
   *
   * Why: the contact constraints of this discretization bound u.n at
   * vertices and (sigma n).n on faces, so a contact zone of a few faces
   * leaves faces where neither is active; the complementarity term couples
   * them only weakly, the contact block is nearly singular, and the
   * truncated coarse spaces cannot represent the pressure on a contact
   * zone smaller than a coarse face: the plain cycle stalls (half disc,
   * doc/results.md). CG removes these few near-singular modes in a handful
   * of steps.
   */
  template <int dim>
  class NewtonStep
  {
  public:
    NewtonStep(const Parameters::Solver &parameters,
               PatchSmoother &           pre_smoother,
               const PatchSmoother &     post_smoother,
               MonotoneCycle<dim> &      cycle,
               MultigridCounters &       counters,
               const unsigned int        finest_level);

    /** One step from @p x; returns the number of linear cycles applied. */
    unsigned int apply(const ConstrainedQP &qp, LevelVector &x);

    /** The finest level's operator changed: its linear roles are gone. */
    void new_fine_operator()
    {
      linear_role_used.clear();
      pair_terms_used = PairTerms();
    }

    /**
     * The most rounds of the Newton direction. Each round fixes at least
     * one more DoF, so the rounds end; they are capped all the same. A cap
     * of a few rounds is too low where the contact zone grows by a vertex
     * per round (doc/performance.md, "Figures behind the code").
     */
    static constexpr unsigned int max_rounds = 20;
    /**
     * The most halvings of the step along the projection path of the 3D
     * friction pairs on their circles (line_search()): 2^-10 of the
     * feasible step is below the smoother's own corrections.
     */
    static constexpr unsigned int max_path_halvings = 10;
    /**
     * The linear solves of all rounds stop at this times the norm of the
     * first round's right-hand side (the residual on the free DoFs), not
     * of their own: a DoF moved to its bound puts a large, local residual
     * next to it, which one cycle removes, and a tolerance relative to
     * that norm stopped CG after 1 step with the smooth part of the error
     * untouched. The direction was then so far off that the best step
     * along it was a fraction of d, every iteration, and the run stalled
     * (doc/performance.md, "Figures behind the code").
     */
    static constexpr double cg_reduction = 1e-3;
    /**
     * Where the direction takes a DoF past its stop (bound, kink or
     * circle) within overshoot_fraction of d, that is by more than a
     * thousand times the way to it, d follows a nearly singular mode of
     * the linear problem, and the rest of d is distorted by it: a round
     * then fixes only the DoFs that d takes to their stops within
     * early_fraction of d, and the rest wait for the next round's
     * direction. In the sliding block on 7 levels (`prm/sliding_block.prm`,
     * 49,922 DoFs) a tangential traction 8e-5 of its slip bound short of
     * it was free, and d took it 7 times past the bound, which also took a
     * normal stress into tension at 0.46 of d. Fixed in the same round,
     * the stress was pinned at 0, the next round then pressed a separated
     * vertex into contact, and the steps along that direction decreased J
     * by about 1e-12 each: 13 Newton steps in that Tresca problem, 3 with
     * the traction fixed first (doc/friction_results.md). Without
     * such an overshoot all DoFs past their stops are fixed at once: on
     * the half disc (4 levels) fixing those within 10 times the first
     * one's fraction took 4 iterations instead of 3. A DoF that d takes
     * past its stop within at_stop_fraction of d sits at it up to
     * round-off (released by its multiplier, or a rounding short of its
     * bound) and is no overshoot: counted as one, the last mesh of
     * `prm/hertz_small_contact.prm` (114,482 DoFs, a DoF 3e-11 of d short
     * of its bound) took a round more, 142 cycles instead of 107.
     */
    static constexpr double overshoot_fraction = 1e-3;
    /** See overshoot_fraction. */
    static constexpr double early_fraction = 0.1;
    /** See overshoot_fraction. */
    static constexpr double at_stop_fraction = 1e-8;

  private:
    /**
     * The roles of the linear problem at @p x with the residual
     * @p residual: a bounded DoF is fixed where its bound holds it (at the
     * bound with a multiplier mu_i = (b - A x)_i >= 0), else free.
     */
    void set_linear_roles(const ConstrainedQP &qp,
                          const LevelVector &  x,
                          const LevelVector &  residual);
    /** pair_terms of pair_curvatures. Collective. */
    void set_pair_terms(const ConstrainedQP &qp);
    /**
     * The fraction t in [0, 1] of the direction @p d at which the 3D
     * friction pair of DoF @p i at @p x reaches its stop: a traction pair
     * its circle, a slip pair (nearest) its kink.
     */
    double pair_stop_fraction(const ConstrainedQP &          qp,
                              unsigned int                   i,
                              const TangentialPair::Vector2 &x,
                              const TangentialPair::Vector2 &d) const;
    /**
     * The Newton direction @p d at @p x (the rounds of PCG); returns the
     * number of linear cycles applied. With 3D traction pairs on their
     * circles that the direction turns, the last round holds them at the
     * points of their circles it turns them to, and tangential_direction
     * keeps the direction before that round (has_tangential_direction).
     */
    unsigned int direction(const ConstrainedQP &qp,
                           const LevelVector &  x,
                           const LevelVector &  residual,
                           LevelVector &        d);
    /**
     * x moves by the best of the feasible steps along @p d (best_step()),
     * and along tangential_direction and first_direction where there are
     * such.
     */
    void line_search(const ConstrainedQP &qp,
                     LevelVector &        x,
                     const LevelVector &  d,
                     const LevelVector &  residual) const;
    /**
     * The better of the two feasible steps along @p d from @p x: its
     * decrease of J, and move()'s arguments for it (@p e, @p t,
     * @p exact_bounds). @p chords: whether the pairs on their circles
     * move along chords of them (held at a point of the circle by the last
     * round of direction()) rather than along their tangents. Collective.
     */
    double best_step(const ConstrainedQP &qp,
                     const LevelVector &  x,
                     const LevelVector &  d,
                     const LevelVector &  residual,
                     const bool           chords,
                     LevelVector &        e,
                     double &             t,
                     bool &               exact_bounds) const;

    /**
     * Where a free DoF @p i of the linear problem that the direction takes
     * to @p y must stop instead: the bound it passes, or (a slip DoF) the
     * kink it crosses from the side of its slope; NaN if none.
     */
    double stop_of(const ConstrainedQP &qp, const unsigned int i, const double y) const;

    /** The linear roles (and slopes) of the 3D friction pair of DoF @p i. */
    void set_pair_role(const ConstrainedQP &qp,
                       const LocalElements &x,
                       const LocalElements &r,
                       const unsigned int   i);
    /**
     * stop_of() for the 3D friction pair of DoF @p i taken to @p y: whether
     * it must stop, and where (@p stop).
     */
    bool pair_stop(const ConstrainedQP &          qp,
                   const unsigned int             i,
                   const TangentialPair::Vector2 &y,
                   const bool                     circles,
                   TangentialPair::Vector2 &      stop) const;
    /** minimizer_along() with the pairs of 3D friction. Collective. */
    double minimizer_along_pairs(const ConstrainedQP &qp,
                                 const LevelVector &  x,
                                 const LevelVector &  e,
                                 const double         eAe,
                                 const double         er,
                                 const double         t_max) const;

    /**
     * The minimizer over [0, @p t_max] of J(x + t e), given e.A.e = @p eAe > 0
     * and e.(b - A x) = @p er, with the kinks of the friction term.
     * Collective.
     */
    double minimizer_along(const ConstrainedQP &qp,
                           const LevelVector &  x,
                           const LevelVector &  e,
                           const double         eAe,
                           const double         er,
                           const double t_max = std::numeric_limits<double>::infinity()) const;
    /** J(x) - J(x + t e), with the kinks of the friction term. Collective. */
    double decrease_at(const ConstrainedQP &qp,
                       const LevelVector &  x,
                       const LevelVector &  e,
                       const double         eAe,
                       const double         er,
                       const double         t) const;
    /**
     * The bound that DoF @p i meets moving in the direction of @p ei: the
     * obstacle (ei > 0), the traction's bound on that side, or a slip
     * DoF's kink; NaN if none.
     */
    static double bound_ahead(const ConstrainedQP &qp, const unsigned int i, const double ei);

    /**
     * x += t e, with the DoFs that reach their bound (or, a slip DoF, its
     * kink) within the step set exactly to it; the obstacles' DoFs only if
     * @p exact_bounds.
     */
    void move(const ConstrainedQP &qp,
              LevelVector &        x,
              const LevelVector &  e,
              const double         t,
              const bool           exact_bounds) const;

    const Parameters::Solver &parameters;
    PatchSmoother &           pre_smoother;
    const PatchSmoother &     post_smoother;
    MonotoneCycle<dim> &      cycle;
    MultigridCounters &       counters;
    const unsigned int        finest;
    /** The linear roles, and those the smoother was last set up with. */
    std::vector<DoFRole> linear_role, linear_role_used;
    /**
     * The slope +-w_i of the friction term at a free slip DoF of the
     * linear problem (owned DoFs; 0 elsewhere): the linear problem's
     * right-hand side is the residual less it.
     */
    std::vector<double> slope;
    /**
     * The free 3D slip pairs of the linear problem, which move along their
     * slip direction only (set_pair_role()).
     */
    std::vector<PairDirection> pair_directions;
    /** The curvatures kappa u u^T the linear problem adds at the pairs. */
    std::vector<PairDirection> pair_curvatures;
    /**
     * The curvatures of the pairs (pair_curvatures) as the linear cycle
     * sees them (PairTerms), and those its smoother was last set up with.
     */
    PairTerms pair_terms, pair_terms_used;
    /** The owned DoFs of traction pairs that move along their circle. */
    std::vector<bool> on_circle;
    /**
     * The direction before direction()'s last round held the pairs on
     * their circles (valid where has_tangential_direction).
     */
    LevelVector tangential_direction;
    bool        has_tangential_direction = false;
    /**
     * With 3D friction, the direction of the first round (valid where
     * has_first_direction: a later round ran), a candidate of
     * line_search().
     */
    LevelVector first_direction;
    bool        has_first_direction = false;
  };
} // namespace FoslsContact

#endif
