#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/monotone_multigrid.h>

namespace FoslsContact
{
  template <int dim>
  MonotoneMultigrid<dim>::MonotoneMultigrid(const Discretization<dim> &discretization,
                                            const LevelTransfer<dim> & transfer,
                                            const unsigned int         finest_level,
                                            const SparsityPattern &    fine_sparsity,
                                            const Parameters::Solver & parameters)
    : level_meshes(discretization.adaptive() && finest_level == discretization.finest_level() ?
                     std::make_unique<const LevelMeshes<dim>>(discretization, transfer) :
                     nullptr)
    , hierarchy(level_meshes ? MultilevelHierarchy<dim>(*level_meshes) :
                               MultilevelHierarchy<dim>(discretization, transfer, finest_level))
    , parameters(parameters)
    , fine_sparsity(&fine_sparsity)
    , finest(hierarchy.finest_level())
    , pre_smoother(
        finest + 1, parameters.pre_smoothing, false, &counters.smoothing, parameters.patch_rows)
    , post_smoother(pre_smoother, parameters.post_smoothing, true)
    // (the plain cycle reroutes the flux of partly truncated coarse faces,
    // the linear cycle their tangential rows with friction in 2D)
    , rerouting(hierarchy,
                fine_sparsity,
                parameters.krylov_steps == 0 ||
                  ContactFaceRelations<dim>::tangential_rows(discretization.get_scene()))
    , operators(hierarchy, fine_sparsity, rerouting)
    , coarse_solver(&counters.coarse_solve)
    , cycle(hierarchy, this->parameters, pre_smoother, post_smoother, operators, coarse_solver, counters)
    , newton_step(this->parameters, pre_smoother, post_smoother, cycle, counters, finest)
  {
    AssertThrow(hierarchy.level(finest).n_dofs == discretization.level(finest_level).n_dofs,
                ExcMessage("monotone multigrid: the hierarchy's finest level is not the "
                           "level it solves on"));
    counters.level_visits.resize(finest + 1);
  }


  template <int dim>
  SolverStatistics
  MonotoneMultigrid<dim>::statistics() const
  {
    SolverStatistics result;
    result.sections = {{"Solve: smoothing", counters.smoothing},
                       {"Solve: Galerkin operators and patch setup", counters.operators},
                       {"Solve: coarse solve", counters.coarse_solve}};
    SolverStatistics::Multilevel multilevel;
    for (unsigned int l = 1; l <= finest; ++l)
      multilevel.patch_colors.push_back(hierarchy.n_colors(l));
    for (unsigned int l = 0; l <= finest; ++l)
      multilevel.level_dofs.push_back(hierarchy.level(l).n_dofs);
    // (level l's visits include those of level l - 1)
    multilevel.level_times = counters.level_visits;
    for (unsigned int l = 1; l <= finest; ++l)
      multilevel.level_times[l].seconds -= counters.level_visits[l - 1].seconds;
    multilevel.level_sweeps             = pre_smoother.sweeps();
    multilevel.coarse_defect_checks     = counters.coarse_defect_checks;
    multilevel.coarse_defect_difference = counters.coarse_defect_difference;
    multilevel.linear_steps             = counters.linear_steps;
    multilevel.linear_log_reduction     = counters.linear_log_reduction;
    // (the pre- and post-smoother share their patches)
    multilevel.memory = {
      {"multigrid: patch smoothers", pre_smoother.memory_consumption()},
      {"multigrid: Galerkin products (index arrays)", operators.product_memory_consumption()},
      {"multigrid: Galerkin operators, truncated prolongations", operators.memory_consumption()},
      {"multigrid: rotated prolongations, vertex patches", hierarchy.memory_consumption()}};
    if (level_meshes)
      multilevel.memory.emplace_back("multigrid: meshes of the adaptive levels",
                                     level_meshes->memory_consumption());
    result.multilevel                   = multilevel;
    return result;
  }


  template <int dim>
  unsigned int
  MonotoneMultigrid<dim>::energy_increases(const ConstrainedQP &qp) const
  {
    return counters.energy_increases +
           Utilities::MPI::sum(pre_smoother.energy_increases(), qp.get_communicator());
  }


  template <int dim>
  unsigned int
  MonotoneMultigrid<dim>::iterate(const ConstrainedQP &qp, LevelVector &x)
  {
    if (parameters.krylov_steps > 0)
      // the fine-level projected smoothing counts as one more cycle
      return newton_step.apply(qp, x) + 1;
    cycle.run(finest, qp.matrix, qp.rhs, qp.upper_bounds, qp.role, x);
    return 1;
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::solve(const ConstrainedQP &qp,
                                LevelVector &        x,
                                IterationObserver &  observer)
  {
    AssertThrow(qp.size() == hierarchy.level(finest).n_dofs,
                ExcMessage("monotone multigrid: problem and hierarchy differ"));
    AssertThrow(&qp.matrix.get_sparsity_pattern() == fine_sparsity &&
                  fine_sparsity->n_nonzero_elements() == qp.matrix.n_nonzero_elements(),
                ExcMessage("monotone multigrid: the problem's matrix is not on the "
                           "pattern the solver was set up for"));
    update_ghosts(x);
    qp.project_to_feasible(x);
    observer.enable_stall_detection();
    observer.enable_divergence_detection();
    observer.start(x);
    {
      const ScopedTime timing(counters.operators);
      cycle.initialize_smoother(finest, qp.matrix, qp.role);
    }
    // (the friction terms of J act on the finest level; its coarse
    // corrections leave them alone, see LevelTruncation)
    pre_smoother.set_friction(finest, qp.has_friction() ? &qp.friction : nullptr);
    operators.new_fine_operator(qp.matrix);
    newton_step.new_fine_operator();

    LevelVector x_old(x);
    AssertThrow(finest > 0 || !qp.has_friction(),
                ExcMessage("the monotone multigrid solves friction on two levels or more: "
                           "on one level take 'Solver/Type' = active set"));
    if (finest == 0)
      {
        // one level: the exact coarse solve is the whole method
        cycle.run(0, qp.matrix, qp.rhs, qp.upper_bounds, qp.role, x);
        observer.report(x, x_old);
        observer.set_converged();
        return;
      }
    for (bool stop = false; !stop;)
      {
        x_old                                = x;
        const unsigned int increases_before  = energy_increases(qp);
        const unsigned int dampings_before   = counters.feasibility_dampings;
        observer.note_cycles(iterate(qp, x));
        observer.note_energy_increases(energy_increases(qp) - increases_before);
        observer.note_feasibility_dampings(counters.feasibility_dampings - dampings_before);
        stop = observer.report(x, x_old);
      }
  }

  template class MonotoneMultigrid<2>;
  template class MonotoneMultigrid<3>;
} // namespace FoslsContact
