#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <fosls_contact/solvers/newton_step.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace FoslsContact
{
  namespace
  {
    /**
     * A restricted to the inactive set: the rows and columns of the fixed
     * DoFs are 0 (@p fixed: the owned ones).
     */
    struct TruncatedOperator
    {
      const SparseMatrix<double> &                A;
      const std::vector<types::global_dof_index> &fixed;
      mutable LevelVector                         tmp;
      void
      vmult(LevelVector &dst, const LevelVector &src) const
      {
        tmp = src;
        for (const auto i : fixed)
          tmp.local_element(i) = 0;
        FoslsContact::vmult(A, dst, tmp);
        for (const auto i : fixed)
          dst.local_element(i) = 0;
      }
    };

    /** The linear truncated cycle as a preconditioner. */
    template <typename Cycle>
    struct CyclePreconditioner
    {
      Cycle cycle;
      void
      vmult(LevelVector &dst, const LevelVector &src) const
      {
        dst = 0;
        cycle(src, dst);
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
    for (unsigned int i = 0; i < qp.role.size(); ++i)
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
    CyclePreconditioner<decltype(apply_cycle)> preconditioner{apply_cycle};
    std::vector<types::global_dof_index>       fixed;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (linear_role[i] == DoFRole::fixed)
        fixed.push_back(i);
    TruncatedOperator op{A, fixed, qp.new_vector()};
    LevelVector increment = qp.new_vector(), rhs = qp.new_vector(), Ae = qp.new_vector();
    double      tolerance = 0;
    for (unsigned int round = 0; round < max_rounds + 1; ++round)
      {
        if (linear_role != linear_role_used)
          {
            const ScopedTime timing(counters.operators);
            pre_smoother.set_linear_roles(finest, linear_role);
            linear_role_used = linear_role;
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
        if (round == 0)
          tolerance = cg_reduction * rhs.l2_norm();
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
        d += increment;
        bool violated = false;
        for (unsigned int i = 0; round < max_rounds && i < n_owned; ++i)
          if (linear_role[i] == DoFRole::free)
            {
              const double stop = stop_of(qp, i, x.local_element(i) + d.local_element(i));
              if (!std::isnan(stop))
                {
                  linear_role[i] = DoFRole::fixed;
                  fixed.push_back(i);
                  increment.local_element(i) = stop - x.local_element(i);
                  violated                   = true;
                }
            }
        if (Utilities::MPI::max(violated ? 1u : 0u, qp.get_communicator()) == 0)
          break;
        // the owners' decisions to the ghost copies (the smoother's roles)
        exchange_ghosts(qp.partitioner, linear_role);
      }
    return n_cycles;
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
              const double z = x.local_element(i) - qp.friction.slip_references.local_element(i);
              kink_change += qp.friction.slip_weights.local_element(i) *
                             (std::abs(z + t * e.local_element(i)) - std::abs(z));
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
      return;
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
    t_feasible               = Utilities::MPI::min(t_feasible, qp.get_communicator());
    const double t_unbounded = minimizer_along(qp, x, d, dAd, dr);
    const double t_d         = std::min(t_unbounded, t_feasible);
    const double decrease_d  = decrease_at(qp, x, d, dAd, dr, t_d);

    step = x;
    step.add(t_unbounded, d);
    qp.project_to_feasible(step);
    step -= x;
    LevelVector As = qp.new_vector();
    vmult(qp.matrix, As, step);
    const double sAs = step * As, sr = step * residual;
    double       t_p = 0, decrease_p = 0;
    if (sAs > 0)
      {
        t_p        = minimizer_along(qp, x, step, sAs, sr, 1.);
        decrease_p = decrease_at(qp, x, step, sAs, sr, t_p);
      }
    if (!(decrease_p > 0) && !(decrease_d > 0))
      return;
    // (the projected step puts the obstacles' DoFs on their bounds
    // already, up to the round-off of x + (ub - x))
    if (decrease_p > decrease_d)
      move(qp, x, step, t_p, false);
    else
      move(qp, x, d, t_d, true);
  }

  template class NewtonStep<2>;
  template class NewtonStep<3>;
} // namespace FoslsContact
