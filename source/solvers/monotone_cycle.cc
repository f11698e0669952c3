#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/coarse_obstacles.h>
#include <fosls_contact/solvers/energy_check.h>
#include <fosls_contact/solvers/monotone_cycle.h>

#include <cmath>

namespace FoslsContact
{
  template <int dim>
  MonotoneCycle<dim>::MonotoneCycle(const MultilevelHierarchy<dim> &hierarchy,
                                    const Parameters::Solver &      parameters,
                                    PatchSmoother &                 pre_smoother,
                                    const PatchSmoother &           post_smoother,
                                    LevelOperators<dim> &           operators,
                                    CoarseSolver &                  coarse_solver,
                                    MultigridCounters &             counters)
    : hierarchy(hierarchy)
    , parameters(parameters)
    , pre_smoother(pre_smoother)
    , post_smoother(post_smoother)
    , operators(operators)
    , coarse_solver(coarse_solver)
    , counters(counters)
    , finest(hierarchy.finest_level())
    , scratch(finest + 1)
  {
    for (unsigned int l = 1; l < finest; ++l)
      if (hierarchy.level(l).n_dofs <= linear_coarse_max_dofs)
        linear_coarsest_level = l;
  }


  template <int dim>
  void
  MonotoneCycle<dim>::initialize_smoother(const unsigned int          l,
                                          const SparseMatrix<double> &A,
                                          const std::vector<DoFRole> &role)
  {
    pre_smoother.initialize_level(l,
                                  A,
                                  hierarchy.patches(l),
                                  hierarchy.patch_colors(l),
                                  hierarchy.n_colors(l),
                                  role,
                                  hierarchy.level(l).partitioner);
  }


  template <int dim>
  void
  MonotoneCycle<dim>::run(const unsigned int          l,
                          const SparseMatrix<double> &A,
                          const LevelVector &         r,
                          const LevelVector &         ub,
                          const std::vector<DoFRole> &role,
                          LevelVector &               v,
                          const bool                  linear,
                          std::optional<Parameters::Solver::Cycle> type)
  {
    using Cycle = Parameters::Solver::Cycle;
    if (!type)
      type = parameters.cycle;
    const ScopedTime visit_time(counters.level_visits[l]);
    if (solved_exactly(l, linear))
      {
        // (the level's partitioner, not v's: every process takes part)
        coarse_solver.solve(
          *hierarchy.level(l).partitioner, A, operators.version_of(l, A).second, r, ub, role, v);
        return;
      }
    smooth(l, pre_smoother, ub, r, v, linear); // (v's ghost values are valid afterwards)
    prepare(l, A, role);
    // (an exact coarse solve needs one visit; a level of an adaptive mesh
    // visits the one below once: where the refinement narrows to a point
    // (a corner, the edge of a contact zone) consecutive levels differ by
    // the few cells around it, and a W-cycle would visit level l up to
    // 2^(L-l) times)
    const unsigned int visits =
      solved_exactly(l - 1, linear) || *type == Cycle::V || hierarchy.adaptive_level(l) ? 1 : 2;
    double             alpha  = 1.; // the damping of the last visit's correction
    for (unsigned int visit = 0; visit < visits; ++visit)
      coarse_correction(l, A, r, ub, role, v, linear, *type, visit, alpha);
    smooth(l, post_smoother, ub, r, v, linear);
    pre_smoother.use_linear_roles(l, false);
  }


  template <int dim>
  void
  MonotoneCycle<dim>::smooth(const unsigned int   l,
                             const PatchSmoother &smoother,
                             const LevelVector &  ub,
                             const LevelVector &  r,
                             LevelVector &        v,
                             const bool           linear)
  {
    // the finest level of the linear cycle relaxes with the linear roles
    // (on coarser levels the truncation takes care of them)
    pre_smoother.use_linear_roles(l, linear && l == finest);
    pre_smoother.set_obstacles(l, ub);
    smoother.smooth(l, v, r);
  }


  template <int dim>
  void
  MonotoneCycle<dim>::prepare(const unsigned int          l,
                              const SparseMatrix<double> &A,
                              const std::vector<DoFRole> &role)
  {
    const auto &fine   = hierarchy.level(l);
    const auto &coarse = hierarchy.level(l - 1);
    Scratch &   work   = scratch[l];
    // (set up on the first visit; a process may own no DoF of the level,
    // so the size of the arrays cannot tell whether they are: the vectors'
    // partitioners can, and without them the vectors would live on
    // MPI_COMM_SELF and the coarse solve's collectives would skip this
    // process)
    if (work.residual.get_partitioner() != fine.partitioner)
      {
        for (auto *vector : {&work.residual, &work.w})
          vector->reinit(fine.partitioner);
        for (auto *vector : {&work.r_coarse, &work.ub_coarse, &work.c, &work.Ac})
          vector->reinit(coarse.partitioner);
      }
    work.truncation.prepare(fine.partitioner, A, operators.version_of(l, A), role);
  }


  template <int dim>
  bool
  MonotoneCycle<dim>::update_operator(const unsigned int          l,
                                      const SparseMatrix<double> &A,
                                      const std::vector<DoFRole> &role,
                                      const bool                  linear)
  {
    const auto reroute = !linear;
    const auto &truncated = scratch[l].truncation.truncated();
    const bool  rebuilt   = operators.needs_update(l, truncated, reroute);
    if (rebuilt)
      {
        const ScopedTime timing(counters.operators);
        operators.update(l, A, role, truncated, reroute);
        // (not for a level the cycle solves exactly, which it does not
        // smooth)
        if (!solved_exactly(l - 1, linear))
          initialize_smoother(l - 1, operators.galerkin(l - 1), hierarchy.level(l - 1).role);
      }
    return rebuilt;
  }


  template <int dim>
  void
  MonotoneCycle<dim>::coarse_correction(const unsigned int              l,
                                        const SparseMatrix<double> &    A,
                                        const LevelVector &             r,
                                        const LevelVector &             ub,
                                        const std::vector<DoFRole> &    role,
                                        LevelVector &                   v,
                                        const bool                      linear,
                                        const Parameters::Solver::Cycle type,
                                        const unsigned int              visit,
                                        double &                        alpha)
  {
    // (the ghost values of v are valid after the smoothing; v changes in a
    // visit)
    if (visit > 0)
      update_ghosts(v);
    Scratch &work = scratch[l];
    work.truncation.truncate(ub, v);
    const bool rebuilt = update_operator(l, A, role, linear);

    // (with pair terms the shortcut below would need P~^T K P~ c too)
    const PairTerms *pair_terms = linear && l == finest ? linear_pair_terms : nullptr;
    if (visit == 0 || rebuilt || pair_terms != nullptr)
      operators.restrict_defect(l, A, r, v, work.residual, work.r_coarse, pair_terms);
    else
      {
        // The truncation is the one of the last visit (always so in the
        // Newton step's linear cycle), so the coarse operator is
        // P~^T A P~ with the same P~, and the coarse defect of
        // v + alpha P~ c is P~^T (r - A v) - alpha P~^T A P~ c =
        // r_coarse - alpha A_{l-1} c, with A_{l-1} c from the last visit:
        // no product with the fine matrix and P~. (The same up to
        // round-off: the cycles and J do not change; doc/performance.md,
        // section 3.)
        work.r_coarse.add(-alpha, work.Ac);
        if (parameters.check_coarse_defects)
          check_coarse_defect(l, A, r, v, work.r_coarse);
      }
    CoarseObstacles::project(parameters.projection,
                             hierarchy.face_relations(l),
                             operators.face_scale(l),
                             work.truncation.defect_obstacle(),
                             work.ub_coarse);
    work.c = 0;
    // (an F-cycle: an F-cycle on the first visit, a V-cycle on the second)
    using Cycle = Parameters::Solver::Cycle;
    run(l - 1,
        operators.galerkin(l - 1),
        work.r_coarse,
        work.ub_coarse,
        hierarchy.level(l - 1).role,
        work.c,
        linear,
        type == Cycle::F && visit == 1 ? Cycle::V : type);
    alpha = correct(l, ub, v);
  }


  template <int dim>
  double
  MonotoneCycle<dim>::correct(const unsigned int l, const LevelVector &ub, LevelVector &v)
  {
    Scratch &          work    = scratch[l];
    const unsigned int n_owned = hierarchy.level(l).n_owned();
    // (c's ghost values are valid after the coarse cycle)
    vmult(operators.truncated_prolongation(l), work.w, work.c, false);
    // keep the iterate feasible (a no-op when K_H is inside K_h)
    const auto &truncated = work.truncation.truncated();
    double      alpha     = 1.;
    for (const auto i : work.truncation.bounded())
      if (i < n_owned && !truncated[i])
        {
          const double wi = work.w.local_element(i), vi = v.local_element(i),
                       ubi = ub.local_element(i);
          if (wi > 0 && vi + wi > ubi)
            alpha = std::min(alpha, std::max(0., (ubi - vi) / wi));
        }
    alpha = Utilities::MPI::min(alpha, hierarchy.level(l).partitioner->get_mpi_communicator());
    if (alpha < 1.)
      ++counters.feasibility_dampings;

    // the change of Q_l: -alpha w.residual + alpha^2/2 w.A w, with
    // w = P~ c: w.residual = c.r_coarse and w.A w = c.A_{l-1} c (the
    // Galerkin product), on the coarse level instead of a product with
    // the fine matrix
    vmult(operators.galerkin(l - 1), work.Ac, work.c, false);
    const double wr = work.c * work.r_coarse, wAw = work.c * work.Ac;
    const double change = -alpha * wr + 0.5 * alpha * alpha * wAw;
    if (increases_energy(change, std::abs(alpha * wr) + 0.5 * alpha * alpha * std::abs(wAw)))
      ++counters.energy_increases;
    v.add(alpha, work.w);
    for (const auto i : work.truncation.bounded())
      if (i < n_owned && v.local_element(i) > ub.local_element(i))
        v.local_element(i) = ub.local_element(i); // round-off of the damped step only
    return alpha;
  }


  template <int dim>
  void
  MonotoneCycle<dim>::check_coarse_defect(const unsigned int          l,
                                          const SparseMatrix<double> &A,
                                          const LevelVector &         r,
                                          const LevelVector &         v,
                                          const LevelVector &         r_coarse)
  {
    const double d = operators.coarse_defect_difference(l, A, r, v, r_coarse);
    ++counters.coarse_defect_checks;
    // (once NaN, the result stays NaN, which std::max would drop)
    double &largest = counters.coarse_defect_difference;
    if (!std::isnan(largest) && (std::isnan(d) || d > largest))
      largest = d;
  }

  template class MonotoneCycle<2>;
  template class MonotoneCycle<3>;
} // namespace FoslsContact
