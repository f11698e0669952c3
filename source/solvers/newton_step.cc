#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <fosls_contact/solvers/newton_step.h>

#include <algorithm>
#include <limits>

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
    // (the ghost DoFs too, whose entries are valid here: see LocalElements)
    const LocalElements x_local(x), ub(qp.upper_bounds), r(residual);
    linear_role = qp.role;
    for (unsigned int i = 0; i < qp.role.size(); ++i)
      if (qp.role[i] == DoFRole::bounded)
        linear_role[i] = (x_local(i) >= ub(i) && r(i) >= 0) ?
                           DoFRole::fixed :
                           DoFRole::free;
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
          if (qp.role[i] == DoFRole::bounded && linear_role[i] == DoFRole::free &&
              x.local_element(i) + d.local_element(i) > qp.upper_bounds.local_element(i))
            {
              linear_role[i] = DoFRole::fixed;
              fixed.push_back(i);
              increment.local_element(i) = qp.upper_bounds.local_element(i) - x.local_element(i);
              violated                   = true;
            }
        if (Utilities::MPI::max(violated ? 1u : 0u, qp.get_communicator()) == 0)
          break;
        // the owners' decisions to the ghost copies (the smoother's roles)
        exchange_ghosts(qp.partitioner, linear_role);
      }
    return n_cycles;
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
    //    minimizer alpha* = d.r / d.A.d, cut back to the largest t with
    //    x + t d in K (J decreases by convexity). After the rounds of
    //    direction() x + d is in K, with the DoFs they fixed exactly at
    //    their bound.
    // b) The projected Newton step p = P_K(x + alpha* d): every point of
    //    the segment [x, p] is feasible (K is convex) and J is a quadratic
    //    on it, so its minimizer t in (0, 1] is taken when p - x is a
    //    descent direction.
    // b) alone is not enough: where the DoFs fixed by the rounds have
    //    positive multipliers, alpha* > 1, and p cuts them back to their
    //    bound while the rest of p moves on as if they did not: p - x
    //    has far more energy than d, the step along it decreases J far
    //    less than x + d, and the run stalls (doc/performance.md, "Figures behind the code").
    const auto  n_owned = qp.n_owned();
    LevelVector Ad = qp.new_vector(), step = qp.new_vector();
    vmult(qp.matrix, Ad, d);
    const double dAd = d * Ad, dr = d * residual;
    if (!(dAd > 0) || !(dr > 0))
      return;
    auto step_to_bound = [&](const unsigned int i) {
      return std::max(0., (qp.upper_bounds.local_element(i) - x.local_element(i)) /
                            d.local_element(i));
    };
    double t_d = dr / dAd;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (qp.role[i] == DoFRole::bounded && d.local_element(i) > 0)
        t_d = std::min(t_d, step_to_bound(i));
    t_d                     = Utilities::MPI::min(t_d, qp.get_communicator());
    const double decrease_d = t_d * (dr - 0.5 * t_d * dAd);

    step = x;
    step.add(dr / dAd, d);
    qp.project_to_feasible(step);
    step -= x;
    LevelVector As = qp.new_vector();
    vmult(qp.matrix, As, step);
    const double sAs = step * As, sr = step * residual;
    double       t_p = 0, decrease_p = 0;
    if (sAs > 0 && sr > 0)
      {
        t_p        = std::min(1., sr / sAs);
        decrease_p = t_p * (sr - 0.5 * t_p * sAs);
      }
    if (decrease_p > decrease_d)
      x.add(t_p, step);
    else
      {
        // the DoFs that limit t_d end exactly at their bound (not a
        // rounding below it, which would leave them inactive)
        std::vector<unsigned int> limiting;
        for (unsigned int i = 0; i < n_owned; ++i)
          if (qp.role[i] == DoFRole::bounded && d.local_element(i) > 0 &&
              step_to_bound(i) <= t_d)
            limiting.push_back(i);
        x.add(t_d, d);
        for (const auto i : limiting)
          x.local_element(i) = qp.upper_bounds.local_element(i);
      }
    qp.project_to_feasible(x); // round-off only
  }

  template class NewtonStep<2>;
  template class NewtonStep<3>;
} // namespace FoslsContact
