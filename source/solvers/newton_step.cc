#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <fosls_contact/qp/tangential_pair.h>
#include <fosls_contact/solvers/newton_step.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace FoslsContact
{
  namespace
  {
    /**
     * The 3D friction pairs that move along one direction only:
     * v_pair <- (v_pair . u) u (owned DoFs).
     */
    void
    project_pairs(const std::vector<PairDirection> &along, LevelVector &v)
    {
      for (const auto &[i, j, u, kappa] : along)
        {
          (void)kappa;
          const double a     = v.local_element(i) * u[0] + v.local_element(j) * u[1];
          v.local_element(i) = a * u[0];
          v.local_element(j) = a * u[1];
        }
    }

    /**
     * The Newton matrix of the linear problem, A restricted to the inactive
     * set (the rows and columns of the fixed DoFs are 0, @p fixed: the
     * owned ones) and to the directions of the pairs that move along one
     * (@p along), plus the curvature kappa u u^T of the pairs' norms and
     * circles (@p curved).
     */
    struct TruncatedOperator
    {
      const SparseMatrix<double> &                A;
      const std::vector<types::global_dof_index> &fixed;
      const std::vector<PairDirection> &          along;
      const std::vector<PairDirection> &          curved;
      mutable LevelVector                         tmp;
      void
      vmult(LevelVector &dst, const LevelVector &src) const
      {
        tmp = src;
        for (const auto i : fixed)
          tmp.local_element(i) = 0;
        project_pairs(along, tmp);
        FoslsContact::vmult(A, dst, tmp);
        for (const auto &[i, j, u, kappa] : curved)
          {
            const double a = kappa * (tmp.local_element(i) * u[0] + tmp.local_element(j) * u[1]);
            dst.local_element(i) += a * u[0];
            dst.local_element(j) += a * u[1];
          }
        for (const auto i : fixed)
          dst.local_element(i) = 0;
        project_pairs(along, dst);
      }
    };

    /** The linear truncated cycle as a preconditioner. */
    template <typename Cycle>
    struct CyclePreconditioner
    {
      Cycle                             cycle;
      const std::vector<PairDirection> &along;
      /** Whether the problem has 3D friction pairs (on every process alike). */
      const bool                        pairs;
      mutable LevelVector               tmp;
      void
      vmult(LevelVector &dst, const LevelVector &src) const
      {
        dst = 0;
        if (!pairs)
          {
            cycle(src, dst);
            return;
          }
        // (P B P with the projection P onto the pairs' directions: SPD on
        // the subspace CG works in)
        tmp = src;
        project_pairs(along, tmp);
        cycle(tmp, dst);
        project_pairs(along, dst);
      }
    };
  } // namespace


  template <int dim>
  NewtonStep<dim>::NewtonStep(const Parameters::Solver &parameters,
                              PatchSmoother &           pre_smoother,
                              const PatchSmoother &     post_smoother,
                              MonotoneCycle<dim> &      cycle,
                              MultigridCounters &       counters,
                              const unsigned int        finest_level)
    : parameters(parameters)
    , pre_smoother(pre_smoother)
    , post_smoother(post_smoother)
    , cycle(cycle)
    , counters(counters)
    , finest(finest_level)
  {}


  template <int dim>
  unsigned int
  NewtonStep<dim>::apply(const ConstrainedQP &qp, LevelVector &x)
  {
    pre_smoother.set_obstacles(finest, qp.upper_bounds);
    pre_smoother.smooth(finest, x, qp.rhs);

    LevelVector residual = qp.new_vector(), d = qp.new_vector();
    vmult(qp.matrix, residual, x, false); // (x's ghosts: after the smoothing)
    residual.sadd(-1., 1., qp.rhs);
    update_ghosts(residual);
    set_linear_roles(qp, x, residual);
    const unsigned int n_cycles = direction(qp, x, residual, d);
    line_search(qp, x, d, residual);

    pre_smoother.set_obstacles(finest, qp.upper_bounds);
    post_smoother.smooth(finest, x, qp.rhs);
    return n_cycles;
  }


  template <int dim>
  void
  NewtonStep<dim>::set_linear_roles(const ConstrainedQP &qp,
                                    const LevelVector &  x,
                                    const LevelVector &  residual)
  {
    // A DoF that sits at its bound while the gradient pulls it inside
    // (mu_i < 0) is left free, so that the Newton direction can release it.
    // With friction the same for a traction at either of its bounds, and a
    // slip DoF is held at its kink where the kink holds it (|mu_i| <= w_i);
    // a free slip DoF carries the slope of its side (or, at its kink, of
    // the side mu_i pulls it to) into the linear problem.
    // (the ghost DoFs too, whose entries are valid here: see LocalElements)
    const LocalElements x_local(x), ub(qp.upper_bounds), r(residual);
    const bool          friction = qp.has_friction();
    linear_role                  = qp.role;
    slope.assign(qp.n_owned(), 0.);
    pair_directions.clear();
    pair_curvatures.clear();
    on_circle.assign(qp.n_owned(), false);
    for (unsigned int i = 0; i < qp.role.size(); ++i)
      if (friction && qp.friction.partner_of(i) != FrictionTerms::no_partner)
        set_pair_role(qp, x_local, r, i);
      else
        switch (qp.role[i])
          {
            case DoFRole::bounded:
              linear_role[i] =
                (x_local(i) >= ub(i) && r(i) >= 0) ? DoFRole::fixed : DoFRole::free;
              break;
            case DoFRole::traction:
              {
                const double s = friction ? qp.friction.traction_bounds.local_element(i) :
                                            std::numeric_limits<double>::infinity();
                linear_role[i] = (x_local(i) >= s && r(i) >= 0) || (x_local(i) <= -s && r(i) <= 0) ?
                                   DoFRole::fixed :
                                   DoFRole::free;
                break;
              }
            case DoFRole::slip:
              {
                linear_role[i] = DoFRole::free;
                if (!friction)
                  break;
                const double w = qp.friction.slip_weights.local_element(i);
                const double z = x_local(i) - qp.friction.slip_references.local_element(i);
                if (z == 0 && std::abs(r(i)) <= w)
                  linear_role[i] = DoFRole::fixed;
                else if (i < qp.n_owned())
                  slope[i] = (z > 0 || (z == 0 && r(i) > 0)) ? w : -w;
                break;
              }
            default:
              break;
          }
    if (friction && qp.friction.has_pairs())
      set_pair_terms(qp);
  }


  template <int dim>
  void
  NewtonStep<dim>::set_pair_terms(const ConstrainedQP &qp)
  {
    // K of the owned pairs, then to the ghost copies (a patch of this
    // process may hold a pair another process owns)
    LevelVector diagonal = qp.new_vector(), coupling = qp.new_vector();
    for (const auto &[i, j, u, kappa] : pair_curvatures)
      {
        diagonal.local_element(i) += kappa * u[0] * u[0];
        diagonal.local_element(j) += kappa * u[1] * u[1];
        coupling.local_element(i) += kappa * u[0] * u[1];
        coupling.local_element(j) += kappa * u[0] * u[1];
      }
    const auto local_copy = [](const LevelVector &v, std::vector<double> &copy) {
      update_ghosts(v);
      const LocalElements local(v);
      copy.assign(local.begin(), local.begin() + local.size());
    };
    local_copy(diagonal, pair_terms.diagonal);
    local_copy(coupling, pair_terms.coupling);
    pair_terms.partner = qp.friction.partner;
  }


  template <int dim>
  void
  NewtonStep<dim>::set_pair_role(const ConstrainedQP &qp,
                                 const LocalElements &x,
                                 const LocalElements &r,
                                 const unsigned int   i)
  {
    // A 3D pair (FrictionTerms::partner) is the Newton step of the pair's
    // own nonsmooth term at the iterate:
    // - a traction pair inside its disc is free;
    // - one on its circle whose multiplier mu = r . x / |x| >= 0 pushes it
    //   outwards moves along the circle's tangent t only, with the
    //   curvature mu / s of the circle (the Hessian of the Lagrangian);
    // - a slip pair at its reference is held where the norm's kink holds
    //   it (|r| <= w), else it starts to slip along r with the slope w;
    // - a sliding slip pair z = x - p != 0 is free with the gradient
    //   w z / |z| of the norm and its curvature w / |z| across z.
    // The angle of a traction on its circle and the direction of a slip
    // are continuous unknowns set by the whole elastic field: held, they
    // are left to the smoother alone, whose corrections are local, and
    // without the curvature the direction overshoots them and the line
    // search cuts the steps short (doc/method.md section 7.7). A curvature
    // above curvature_limit times the pair's diagonal of A holds its
    // direction instead: a stiff local mode, which the smoother's pair
    // blocks take, and which costs the preconditioned CG steps (the
    // cycle sees the curvature on the finest level only, PairTerms).
    constexpr double   curvature_limit = 10;
    const unsigned int j               = qp.friction.partner_of(i);
    if (j < i)
      return;
    const TangentialPair::Vector2 xp{x(i), x(j)}, rp{r(i), r(j)};
    const bool                    owned = i < qp.n_owned();
    const double diagonal = owned ? std::max(qp.matrix.diag_element(i), qp.matrix.diag_element(j)) : 0.;
    bool         held     = false;
    if (qp.role[i] == DoFRole::traction)
      {
        const double s      = qp.friction.traction_bounds.local_element(i);
        const double length = TangentialPair::norm(xp);
        const double mu     = length > 0 ? (rp[0] * xp[0] + rp[1] * xp[1]) / length : 0.;
        if (length >= s * (1 - 1e-12) && mu >= 0)
          {
            const double kappa = s > 0 ? mu / s : std::numeric_limits<double>::infinity();
            held               = !(kappa <= curvature_limit * diagonal) || length == 0;
            if (!held && owned)
              {
                const TangentialPair::Vector2 t{-xp[1] / length, xp[0] / length};
                pair_directions.push_back({i, j, t, 0.});
                pair_curvatures.push_back({i, j, t, kappa});
                on_circle[i] = on_circle[j] = true;
              }
          }
      }
    else
      {
        const double                  w = qp.friction.slip_weights.local_element(i);
        const TangentialPair::Vector2 z{xp[0] - qp.friction.slip_references.local_element(i),
                                        xp[1] - qp.friction.slip_references.local_element(j)};
        const double                  length = TangentialPair::norm(z);
        held = length == 0 && TangentialPair::norm(rp) <= w;
        if (!held && owned)
          {
            const TangentialPair::Vector2 toward = length == 0 ? rp : z;
            const double                  size   = TangentialPair::norm(toward);
            const TangentialPair::Vector2 u{toward[0] / size, toward[1] / size};
            slope[i]           = w * u[0];
            slope[j]           = w * u[1];
            const double kappa = length > 0 ? w / length : std::numeric_limits<double>::infinity();
            if (kappa <= curvature_limit * diagonal)
              pair_curvatures.push_back({i, j, {-u[1], u[0]}, kappa});
            else
              pair_directions.push_back({i, j, u, 0.});
          }
      }
    linear_role[i] = linear_role[j] = held ? DoFRole::fixed : DoFRole::free;
  }


  template <int dim>
  bool
  NewtonStep<dim>::pair_stop(const ConstrainedQP &          qp,
                             const unsigned int             i,
                             const TangentialPair::Vector2 &y,
                             const bool                     circles,
                             TangentialPair::Vector2 &      stop) const
  {
    // a traction pair that the direction takes out of its disc stops on
    // the circle where the radius through y meets it; a slip pair whose
    // slip the direction turns against the slope it was linearized with
    // stops at its reference (the kink), as a 2D slip DoF that crosses it
    const unsigned int j = qp.friction.partner_of(i);
    if (qp.role[i] == DoFRole::traction)
      {
        // (a pair that moves along its circle leaves it to second order
        // only: it stops on it in the last round alone, @p circles)
        const double s = qp.friction.traction_bounds.local_element(i);
        if ((on_circle[i] && !circles) || !(TangentialPair::norm(y) > s))
          return false;
        stop = TangentialPair::project_to_disc(y, s);
        return true;
      }
    if (slope[i] == 0 && slope[j] == 0)
      return false;
    const TangentialPair::Vector2 p{qp.friction.slip_references.local_element(i),
                                    qp.friction.slip_references.local_element(j)};
    if ((y[0] - p[0]) * slope[i] + (y[1] - p[1]) * slope[j] > 0)
      return false;
    stop = p;
    return true;
  }


  template <int dim>
  unsigned int
  NewtonStep<dim>::direction(const ConstrainedQP &qp,
                             const LevelVector &  x,
                             const LevelVector &  residual,
                             LevelVector &        d)
  {
    // d = increment + (the solution of the linear problem on the free DoFs). A
    // free DoF that the direction would push past its bound is moved exactly to
    // its bound instead (a prescribed increment) and the linear problem is
    // solved again without it: otherwise the projection in the line search cuts
    // such a DoF back, and the rest of the direction, computed for it moving
    // on, is far from a good step (doc/performance.md, "Figures behind the
    // code").
    const auto &   A       = qp.matrix;
    const auto     n_owned = qp.n_owned();
    unsigned int   n_cycles = 0;
    LevelVector    infinite = qp.new_vector();
    infinite                = std::numeric_limits<double>::infinity();
    auto           apply_cycle = [&](const LevelVector &r, LevelVector &v) {
      cycle.run(finest, A, r, infinite, linear_role, v, true);
      ++n_cycles;
    };
    const bool pairs = qp.has_friction() && qp.friction.has_pairs();
    CyclePreconditioner<decltype(apply_cycle)> preconditioner{apply_cycle,
                                                              pair_directions,
                                                              pairs,
                                                              qp.new_vector()};
    std::vector<types::global_dof_index>       fixed;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (linear_role[i] == DoFRole::fixed)
        fixed.push_back(i);
    TruncatedOperator op{A, fixed, pair_directions, pair_curvatures, qp.new_vector()};
    LevelVector increment = qp.new_vector(), rhs = qp.new_vector(), Ae = qp.new_vector();
    double      tolerance = 0;
    // (the last round, after no DoF passes its bound any more: the pairs
    // on their circles held where the direction turns them; see below)
    bool circle_round        = false;
    has_tangential_direction = false;
    has_first_direction      = false;
    for (unsigned int round = 0; round < max_rounds + 1; ++round)
      {
        if (linear_role != linear_role_used || !(pair_terms == pair_terms_used))
          {
            const ScopedTime timing(counters.operators);
            pre_smoother.set_linear_roles(finest,
                                          linear_role,
                                          pair_terms.empty() ? nullptr : &pair_terms);
            linear_role_used = linear_role;
            pair_terms_used  = pair_terms;
          }
        rhs = residual;
        if (round > 0) // the increment is zero until a DoF was moved to its bound
          {
            vmult(A, Ae, increment);
            rhs -= Ae;
          }
        for (unsigned int i = 0; i < n_owned; ++i)
          if (linear_role[i] == DoFRole::fixed)
            rhs.local_element(i) = 0;
          else
            rhs.local_element(i) -= slope[i];
        project_pairs(pair_directions, rhs);
        if (round == 0)
          tolerance = cg_reduction * rhs.l2_norm();
        cycle.set_linear_pair_terms(pair_terms.empty() ? nullptr : &pair_terms);
        SolverControl         control(parameters.krylov_steps, tolerance, false, false);
        SolverCG<LevelVector> cg(control);
        // round 0 starts from zero; a later round from the last round's
        // solution (d less its increment, which is zero off the fixed DoFs)
        // with the DoFs it fixed at zero: the residual of that is the local
        // one next to them, not the whole Newton residual again
        if (round == 0)
          d = 0;
        else
          {
            d -= increment;
            for (const auto i : fixed)
              d.local_element(i) = 0;
          }
        try
          {
            cg.solve(op, d, rhs, preconditioner);
          }
        catch (const SolverControl::NoConvergence &)
          {
            // at most krylov_steps steps: the last iterate is the direction
          }
        // (the linear cycle's rate: MultigridCounters::linear_steps; the
        // norms are global, so every process adds the same)
        if (control.last_step() > 0 && control.initial_value() > 0 && control.last_value() > 0)
          {
            counters.linear_steps += control.last_step();
            counters.linear_log_reduction +=
              std::log(control.last_value() / control.initial_value());
          }
        cycle.set_linear_pair_terms(nullptr);
        d += increment;
        // (3D friction: the first round's direction is a candidate of the
        // line search; see line_search())
        if (pairs && round == 0)
          first_direction = d;
        else if (pairs)
          has_first_direction = true;
        if (circle_round)
          break;
        // (with_circles: the pairs on their circles stop too, all of them)
        const auto stop_violations = [&](const bool with_circles) {
          // the DoFs that pass their stop: (DoF, its stop, the fraction of
          // d at which it reaches it)
          std::vector<std::tuple<unsigned int, double, double>> stops;
          for (unsigned int i = 0; round < max_rounds && i < n_owned; ++i)
            if (linear_role[i] == DoFRole::free && qp.has_friction() &&
                qp.friction.partner_of(i) != FrictionTerms::no_partner)
              {
                const unsigned int            j = qp.friction.partner_of(i);
                const TangentialPair::Vector2 xp{x.local_element(i), x.local_element(j)},
                  dp{d.local_element(i), d.local_element(j)};
                TangentialPair::Vector2 stop;
                if (j > i && pair_stop(qp, i, {xp[0] + dp[0], xp[1] + dp[1]}, with_circles, stop))
                  {
                    const double t = pair_stop_fraction(qp, i, xp, dp);
                    stops.emplace_back(i, stop[0], t);
                    stops.emplace_back(j, stop[1], t);
                  }
              }
            else if (linear_role[i] == DoFRole::free && !with_circles)
              {
                const double stop = stop_of(qp, i, x.local_element(i) + d.local_element(i));
                const double di   = d.local_element(i);
                if (!std::isnan(stop))
                  stops.emplace_back(i,
                                     stop,
                                     di != 0 ? std::clamp((stop - x.local_element(i)) / di, 0., 1.) : 0.);
              }
          // (a DoF at its stop up to round-off that d takes past it, t at
          // most at_stop_fraction, is one that set_linear_roles() released
          // or one a rounding short of its bound: not an overshoot)
          double first = 1;
          for (const auto &stop : stops)
            if (std::get<2>(stop) > at_stop_fraction)
              first = std::min(first, std::get<2>(stop));
          first             = Utilities::MPI::min(first, qp.get_communicator());
          const double last = with_circles || first >= overshoot_fraction ? 1. : early_fraction;
          bool         violated = false;
          for (const auto &[k, value, t] : stops)
            if (t <= last)
              {
                linear_role[k] = DoFRole::fixed;
                fixed.push_back(k);
                increment.local_element(k) = value - x.local_element(k);
                violated                   = true;
              }
          return Utilities::MPI::max(violated ? 1u : 0u, qp.get_communicator()) == 1;
        };
        if (!stop_violations(false))
          {
            // No DoF passes its bound. A pair on its circle that d turns
            // leaves the circle along its tangent; P_K takes it back onto
            // the circle radially, a local move against the stiffness of
            // A, which the rest of d does not follow: that costs J to
            // fourth order in the step and dwarfs the model's decrease
            // where d turns the traction by a few tenths of its radius
            // (the 3D Cattaneo-Mindlin pull: J along P_K(x + t d) rose
            // like t^4 to 3,000 times the model's decrease at t = 1, and
            // the iteration crawled at 0.97 per step on the steps of
            // the halved path). One more round holds such pairs at the
            // points of their circles d turns them to and solves for the
            // rest, which then follows them; the line search compares
            // that direction with d (both feasible, J never increases).
            // (round < max_rounds: else the cap of the rounds has been
            // reached and d stays as it is)
            if (round >= max_rounds || !qp.has_friction() || !qp.friction.has_pairs())
              break;
            tangential_direction = d;
            if (!stop_violations(true))
              break;
            has_tangential_direction = true;
            circle_round             = true;
          }
        // the owners' decisions to the ghost copies (the smoother's roles)
        exchange_ghosts(qp.partitioner, linear_role);
      }
    return n_cycles;
  }


  template <int dim>
  double
  NewtonStep<dim>::pair_stop_fraction(const ConstrainedQP &          qp,
                                      const unsigned int             i,
                                      const TangentialPair::Vector2 &x,
                                      const TangentialPair::Vector2 &d) const
  {
    // a traction pair leaves its disc where |x + t d| = s; a slip pair
    // passes its kink p nearest where d passes p
    const double a = d[0] * d[0] + d[1] * d[1];
    if (!(a > 0))
      return 0.;
    const unsigned int j = qp.friction.partner_of(i);
    if (qp.role[i] == DoFRole::traction)
      return std::min(1., TangentialPair::disc_exit(x, d, qp.friction.traction_bounds.local_element(i)));
    const double p_0 = qp.friction.slip_references.local_element(i),
                 p_1 = qp.friction.slip_references.local_element(j);
    return std::clamp(((p_0 - x[0]) * d[0] + (p_1 - x[1]) * d[1]) / a, 0., 1.);
  }


  template <int dim>
  double
  NewtonStep<dim>::stop_of(const ConstrainedQP &qp, const unsigned int i, const double y) const
  {
    const double none = std::numeric_limits<double>::quiet_NaN();
    switch (qp.role[i])
      {
        case DoFRole::bounded:
          return y > qp.upper_bounds.local_element(i) ? qp.upper_bounds.local_element(i) : none;
        case DoFRole::traction:
          {
            if (!qp.has_friction())
              return none;
            const double s = qp.friction.traction_bounds.local_element(i);
            return y > s ? s : y < -s ? -s : none;
          }
        case DoFRole::slip:
          {
            if (slope[i] == 0)
              return none;
            const double p = qp.friction.slip_references.local_element(i);
            return (slope[i] > 0 && y < p) || (slope[i] < 0 && y > p) ? p : none;
          }
        default:
          return none;
      }
  }


  template <int dim>
  double
  NewtonStep<dim>::minimizer_along(const ConstrainedQP &qp,
                                   const LevelVector &  x,
                                   const LevelVector &  e,
                                   const double         eAe,
                                   const double         er,
                                   const double         t_max) const
  {
    // J(x + t e) - J(x) = -t e.r + t^2/2 e.A.e + sum_i w_i (|z_i + t e_i| - |z_i|)
    // (z = x - p on the slip DoFs): convex and piecewise quadratic, with
    // its kinks where a slip DoF crosses its reference. Its right
    // derivative is -e.r + t e.A.e + sum_i w_i e_i sgn+(z_i + t e_i), which
    // jumps by 2 w_i |e_i| at the kink t_i = -z_i / e_i > 0: the minimizer
    // is found by walking the kinks in order (the same on every process:
    // all of them are gathered).
    if (qp.has_friction() && qp.friction.has_pairs())
      return minimizer_along_pairs(qp, x, e, eAe, er, t_max);
    double                                 slope0 = 0;
    std::vector<std::pair<double, double>> kinks;
    if (qp.has_friction())
      {
        std::vector<double> local; // (t_i, jump_i) pairs
        for (unsigned int i = 0; i < qp.n_owned(); ++i)
          if (qp.role[i] == DoFRole::slip && e.local_element(i) != 0 &&
              qp.friction.slip_weights.local_element(i) > 0)
            {
              const double w  = qp.friction.slip_weights.local_element(i);
              const double ei = e.local_element(i);
              const double z  = x.local_element(i) - qp.friction.slip_references.local_element(i);
              if (z == 0 || (z > 0) == (ei > 0))
                slope0 += w * std::abs(ei);
              else
                {
                  slope0 -= w * std::abs(ei);
                  local.push_back(-z / ei);
                  local.push_back(2 * w * std::abs(ei));
                }
            }
        const MPI_Comm comm = qp.get_communicator();
        slope0              = Utilities::MPI::sum(slope0, comm);
        for (const auto &part : Utilities::MPI::all_gather(comm, local))
          for (std::size_t k = 0; k + 1 < part.size(); k += 2)
            kinks.emplace_back(part[k], part[k + 1]);
        std::sort(kinks.begin(), kinks.end());
      }

    // walk the pieces [t_k, t_{k+1}] until the derivative turns >= 0
    double t = 0, derivative = slope0 - er; // the right derivative at t, without t e.A.e
    for (unsigned int k = 0; k <= kinks.size(); ++k)
      {
        const double next = std::min(t_max, k < kinks.size() ? kinks[k].first : t_max);
        if (derivative + t * eAe >= 0)
          break;
        const double root = eAe > 0 ? -derivative / eAe : std::numeric_limits<double>::infinity();
        if (root <= next)
          return root;
        t = next;
        if (t >= t_max)
          break;
        derivative += kinks[k].second;
      }
    return std::isfinite(t) ? t : 0.;
  }


  template <int dim>
  double
  NewtonStep<dim>::minimizer_along_pairs(const ConstrainedQP &qp,
                                         const LevelVector &  x,
                                         const LevelVector &  e,
                                         const double         eAe,
                                         const double         er,
                                         const double         t_max) const
  {
    // With the pairs of 3D friction J(x + t e) is convex but no longer
    // piecewise quadratic: its right derivative
    //   -e.r + t e.A.e + sum w (z + t e) . e / |z + t e|
    // (w |e| where z + t e = 0; a 2D-like entry alone as in
    // minimizer_along()) is nondecreasing, and its sign change is found by
    // bisection to the last bit. Every process gathers all the terms
    // (w, z, e) of the slip DoFs that move, so all find the same t.
    std::vector<double> local; // w, z_1, z_2, e_1, e_2 per term
    for (unsigned int i = 0; i < qp.n_owned(); ++i)
      if (qp.role[i] == DoFRole::slip && qp.friction.slip_weights.local_element(i) > 0)
        {
          const unsigned int j = qp.friction.partner_of(i);
          if (j != FrictionTerms::no_partner && j < i)
            continue;
          const bool   pair = j != FrictionTerms::no_partner;
          const double e_j  = pair ? e.local_element(j) : 0.;
          if (e.local_element(i) == 0 && e_j == 0)
            continue;
          local.insert(local.end(),
                       {qp.friction.slip_weights.local_element(i),
                        x.local_element(i) - qp.friction.slip_references.local_element(i),
                        pair ? x.local_element(j) - qp.friction.slip_references.local_element(j) : 0.,
                        e.local_element(i),
                        e_j});
        }
    std::vector<double> terms;
    for (const auto &part : Utilities::MPI::all_gather(qp.get_communicator(), local))
      terms.insert(terms.end(), part.begin(), part.end());
    double kink_slopes = 0; // sum w |e|: the terms' slopes are at most this
    for (std::size_t k = 0; k < terms.size(); k += 5)
      kink_slopes += terms[k] * std::hypot(terms[k + 3], terms[k + 4]);
    const auto derivative = [&](const double t) {
      double value = -er + t * eAe;
      for (std::size_t k = 0; k < terms.size(); k += 5)
        {
          const double w = terms[k], e_1 = terms[k + 3], e_2 = terms[k + 4];
          const double y_1 = terms[k + 1] + t * e_1, y_2 = terms[k + 2] + t * e_2;
          const double length = std::hypot(y_1, y_2);
          value += length > 0 ? w * (y_1 * e_1 + y_2 * e_2) / length : w * std::hypot(e_1, e_2);
        }
      return value;
    };
    if (derivative(0.) >= 0)
      return 0.;
    // (the derivative is >= 0 where t e.A.e >= e.r + sum w |e|)
    double hi = std::min(t_max, (er + kink_slopes) / eAe);
    if (!std::isfinite(hi))
      return 0.;
    if (derivative(hi) < 0)
      return hi;
    double lo = 0;
    for (unsigned int k = 0; k < 200; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi))
          break;
        (derivative(mid) < 0 ? lo : hi) = mid;
      }
    return lo;
  }


  template <int dim>
  double
  NewtonStep<dim>::decrease_at(const ConstrainedQP &qp,
                               const LevelVector &  x,
                               const LevelVector &  e,
                               const double         eAe,
                               const double         er,
                               const double         t) const
  {
    // (the kinks' change summed per DoF, not as ConstrainedQP::friction_term()
    // at x + t e less at x: the change of a short step would be lost in the
    // round-off of the two sums)
    double kink_change = 0;
    if (qp.has_friction())
      {
        for (unsigned int i = 0; i < qp.n_owned(); ++i)
          if (qp.role[i] == DoFRole::slip)
            {
              const double       z = x.local_element(i) - qp.friction.slip_references.local_element(i);
              const unsigned int j = qp.friction.partner_of(i);
              if (j == FrictionTerms::no_partner)
                kink_change += qp.friction.slip_weights.local_element(i) *
                               (std::abs(z + t * e.local_element(i)) - std::abs(z));
              else if (i < j)
                {
                  // (|a| - |b| as (|a|^2 - |b|^2) / (|a| + |b|): without the
                  // cancellation of two close norms)
                  const double z_j = x.local_element(j) - qp.friction.slip_references.local_element(j);
                  const double a_1 = z + t * e.local_element(i), a_2 = z_j + t * e.local_element(j);
                  const double sum = std::hypot(a_1, a_2) + std::hypot(z, z_j);
                  if (sum > 0)
                    kink_change += qp.friction.slip_weights.local_element(i) *
                                   ((a_1 - z) * (a_1 + z) + (a_2 - z_j) * (a_2 + z_j)) / sum;
                }
            }
        kink_change = Utilities::MPI::sum(kink_change, qp.get_communicator());
      }
    return t * (er - 0.5 * t * eAe) - kink_change;
  }


  template <int dim>
  double
  NewtonStep<dim>::bound_ahead(const ConstrainedQP &qp, const unsigned int i, const double ei)
  {
    const double none = std::numeric_limits<double>::quiet_NaN();
    // (a 3D pair's disc and kink are no bound of one entry: see
    // line_search() and minimizer_along_pairs())
    if (qp.has_friction() && qp.friction.partner_of(i) != FrictionTerms::no_partner)
      return none;
    switch (qp.role[i])
      {
        case DoFRole::bounded:
          return ei > 0 ? qp.upper_bounds.local_element(i) : none;
        case DoFRole::traction:
          return qp.has_friction() && ei != 0 ?
                   (ei > 0 ? 1. : -1.) * qp.friction.traction_bounds.local_element(i) :
                   none;
        case DoFRole::slip:
          return qp.has_friction() && ei != 0 ? qp.friction.slip_references.local_element(i) :
                                                none;
        default:
          return none;
      }
  }


  template <int dim>
  void
  NewtonStep<dim>::move(const ConstrainedQP &qp,
                        LevelVector &        x,
                        const LevelVector &  e,
                        const double         t,
                        const bool           exact_bounds) const
  {
    // the DoFs that reach a bound or kink at t end exactly on it (not a
    // rounding short of it, which would leave them inactive); a slip DoF
    // only if t is its kink, not past it
    std::vector<std::pair<unsigned int, double>> limiting;
    for (unsigned int i = 0; i < qp.n_owned(); ++i)
      {
        const double ei = e.local_element(i), xi = x.local_element(i);
        const double target = bound_ahead(qp, i, ei);
        if (!std::isnan(target) && (target - xi) / ei >= 0 && (target - xi) / ei <= t)
          limiting.emplace_back(i, target);
      }
    x.add(t, e);
    for (const auto &[i, target] : limiting)
      if ((qp.role[i] == DoFRole::bounded && exact_bounds) || qp.role[i] == DoFRole::traction ||
          x.local_element(i) == target ||
          std::abs(x.local_element(i) - target) <=
            1e-14 * (std::abs(target) + std::abs(t * e.local_element(i))))
        x.local_element(i) = target;
    qp.project_to_feasible(x); // round-off only
  }


  template <int dim>
  void
  NewtonStep<dim>::line_search(const ConstrainedQP &qp,
                               LevelVector &        x,
                               const LevelVector &  d,
                               const LevelVector &  residual) const
  {
    // The best step of the candidate directions (the same on every
    // process: the decreases are sums over all of them). With 3D friction
    // the first round's direction d_0 is one: the later rounds prescribe
    // the moves of the DoFs they fix (to a bound, a circle, a kink), and
    // the rest of the direction follows them, which need not descend: in
    // the 3D Cattaneo-Mindlin pull J rose at first order along both d and
    // the direction before the circle round, 0 was their best step, and
    // the iteration crawled on the smoother's steps at 0.99 per iteration.
    // d_0, the Newton step of the model without those moves, descends
    // wherever its CG descends on the model; its projected step then took
    // that Tresca problem to convergence in 9 iterations.
    LevelVector e = qp.new_vector(), e_candidate = qp.new_vector();
    double      t = 0, decrease = 0;
    bool        exact_bounds = false;
    const auto  candidate    = [&](const LevelVector &direction, const bool chords) {
      double       t_c     = 0;
      bool         exact_c = false;
      const double decrease_c =
        best_step(qp, x, direction, residual, chords, e_candidate, t_c, exact_c);
      if (decrease_c > decrease)
        {
          decrease = decrease_c;
          t        = t_c;
          exact_bounds = exact_c;
          e.swap(e_candidate);
        }
    };
    candidate(d, has_tangential_direction);
    if (has_tangential_direction)
      candidate(tangential_direction, false);
    if (has_first_direction)
      candidate(first_direction, false);
    if (decrease > 0)
      move(qp, x, e, t, exact_bounds);
  }


  template <int dim>
  double
  NewtonStep<dim>::best_step(const ConstrainedQP &qp,
                             const LevelVector &  x,
                             const LevelVector &  d,
                             const LevelVector &  residual,
                             const bool           chords,
                             LevelVector &        e_best,
                             double &             t_best,
                             bool &               exact_bounds) const
  {
    // Two feasible steps that decrease J; the one that decreases it more is
    // taken (the same on every process: the decreases are sums over all of
    // them).
    // a) The feasible part of the step along d: x + t d with t the
    //    minimizer of J along d, cut back to the largest t with x + t d in K
    //    (J decreases by convexity). After the rounds of direction() x + d
    //    is in K, with the DoFs they fixed exactly at their bound.
    // b) The projected Newton step p = P_K(x + alpha* d), alpha* the
    //    minimizer of J along d: every point of the segment [x, p] is
    //    feasible (K is convex) and J is convex on it, so its minimizer t
    //    in (0, 1] is taken when p - x is a descent direction.
    // b) alone is not enough: where the DoFs fixed by the rounds have
    //    positive multipliers, alpha* > 1, and p cuts them back to their
    //    bound while the rest of p moves on as if they did not: p - x
    //    has far more energy than d, the step along it decreases J far
    //    less than x + d, and the run stalls (doc/performance.md, "Figures behind the code").
    // With friction J is the quadratic plus the slip DoFs' kinks, and both
    // minimizers along a line are those of that piecewise quadratic
    // (minimizer_along()); without friction they are d.r / d.A.d and its cut.
    const auto  n_owned = qp.n_owned();
    LevelVector Ad = qp.new_vector(), step = qp.new_vector();
    vmult(qp.matrix, Ad, d);
    const double dAd = d * Ad, dr = d * residual;
    if (!(dAd > 0))
      return 0.;
    // (J is convex along d: its minimizer over [0, t_feasible] is the
    // unbounded one, cut there)
    double t_feasible = std::numeric_limits<double>::infinity();
    for (unsigned int i = 0; i < n_owned; ++i)
      if (qp.role[i] == DoFRole::bounded || qp.role[i] == DoFRole::traction)
        {
          const double di = d.local_element(i), bound = bound_ahead(qp, i, di);
          if (!std::isnan(bound))
            t_feasible = std::min(t_feasible, std::max(0., (bound - x.local_element(i)) / di));
        }
    // (a 3D traction pair: the t at which x + t d leaves its disc)
    if (qp.has_friction() && qp.friction.has_pairs())
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const unsigned int j = qp.friction.partner_of(i);
          if (qp.role[i] != DoFRole::traction || j == FrictionTerms::no_partner || j < i ||
              (on_circle[i] && !chords))
            continue;
          t_feasible = std::min(t_feasible,
                                TangentialPair::disc_exit({x.local_element(i), x.local_element(j)},
                                                          {d.local_element(i), d.local_element(j)},
                                                          qp.friction.traction_bounds.local_element(i)));
        }
    t_feasible               = Utilities::MPI::min(t_feasible, qp.get_communicator());
    const double t_unbounded = minimizer_along(qp, x, d, dAd, dr);
    const double t_d         = std::min(t_unbounded, t_feasible);

    // the segment [x, P_K(x + t d)] and the minimizer t_e of J on it: its
    // decrease
    LevelVector As = qp.new_vector();
    const auto  projected = [&](const double t, LevelVector &e, double &t_e) {
      e = x;
      e.add(t, d);
      qp.project_to_feasible(e);
      e -= x;
      vmult(qp.matrix, As, e);
      const double eAe = e * As, er = e * residual;
      t_e              = 0;
      if (!(eAe > 0))
        return 0.;
      t_e = minimizer_along(qp, x, e, eAe, er, 1.);
      return decrease_at(qp, x, e, eAe, er, t_e);
    };
    // (a 3D traction pair that moves along its circle leaves the disc at
    // once, to second order: its step a) is the segment to the projection
    // of x + t_d d, on which J is convex as on b)'s)
    // (a pair held on a chord of its circle stays in its disc up to t = 1:
    // the step along d is exact there)
    const bool circles =
      !chords &&
      Utilities::MPI::max(std::find(on_circle.begin(), on_circle.end(), true) != on_circle.end() ?
                            1u :
                            0u,
                          qp.get_communicator()) == 1;
    LevelVector step_d = qp.new_vector();
    double      t_a    = t_d;
    double      decrease_d =
      circles ? projected(t_d, step_d, t_a) : decrease_at(qp, x, d, dAd, dr, t_d);
    // The Newton model of a pair on its circle is exact to second order in
    // its move along the tangent, but the circle leaves the tangent by
    // |t d|^2 / (2 s), and A's stiffness in that radial direction enters
    // J to fourth order: where the direction turns a traction by a large
    // angle (|t d| a fair fraction of s), the chord to P(x + t_d d) costs
    // far more than the model says and its minimizer is a tiny t (1/100 of
    // t_d in the 3D sliding block, where the iteration then crawls on the
    // smoother's steps). So the projection path t -> P(x + t d) is searched
    // too, halving t while the decrease of the chord's minimizer grows (J
    // along the path is not convex, but smooth: its first maximum of the
    // decrease is taken).
    if (circles)
      {
        LevelVector trial = qp.new_vector();
        double      t     = t_d;
        for (unsigned int k = 0; k < max_path_halvings; ++k)
          {
            t *= 0.5;
            double       t_e      = 0;
            const double decrease = projected(t, trial, t_e);
            if (!(decrease > decrease_d))
              break;
            decrease_d = decrease;
            t_a        = t_e;
            step_d.swap(trial);
          }
      }
    double       t_p        = 0;
    const double decrease_p = projected(t_unbounded, step, t_p);
    // (the projected step puts the obstacles' DoFs on their bounds
    // already, up to the round-off of x + (ub - x))
    exact_bounds = false;
    if (decrease_p > decrease_d)
      {
        e_best.swap(step);
        t_best = t_p;
        return decrease_p;
      }
    if (circles)
      {
        e_best.swap(step_d);
        t_best = t_a;
      }
    else
      {
        e_best       = d;
        t_best       = t_d;
        exact_bounds = true;
      }
    return decrease_d;
  }

  template class NewtonStep<2>;
  template class NewtonStep<3>;
} // namespace FoslsContact
