#include <fosls_contact/solvers/linear_multigrid.h>

#include <limits>

namespace FoslsContact
{
  namespace
  {
    Multigrid<LevelVector>::Cycle
    multigrid_cycle(const Parameters::Solver::Cycle cycle)
    {
      using Cycle = Parameters::Solver::Cycle;
      return cycle == Cycle::V ? Multigrid<LevelVector>::v_cycle :
             cycle == Cycle::W ? Multigrid<LevelVector>::w_cycle :
                                 Multigrid<LevelVector>::f_cycle;
    }
  } // namespace


  template <int dim>
  LinearMultigrid<dim>::LinearMultigrid(const MultilevelHierarchy<dim> &hierarchy,
                                        const Parameters::Solver &      parameters,
                                        PatchSmoother &                 pre_smoother,
                                        const PatchSmoother &           post_smoother,
                                        MonotoneCycle<dim> &            cycle,
                                        LevelOperators<dim> &           operators,
                                        CoarseSolver &                  coarse_solver,
                                        MultigridCounters &             counters)
    : pre_smoother(pre_smoother)
    , cycle(cycle)
    , counters(counters)
    , finest(hierarchy.finest_level())
    , infinite(finest + 1)
    , transfer(hierarchy, operators)
    , matrices(hierarchy, operators, cycle.linear_coarsest())
    , pre(pre_smoother, pre_smoother, finest, infinite)
    , post(pre_smoother, post_smoother, finest, infinite)
    , coarse(hierarchy, operators, coarse_solver, infinite)
    , multigrid(matrices,
                coarse,
                transfer,
                pre,
                post,
                cycle.linear_coarsest(),
                finest,
                multigrid_cycle(parameters.cycle))
    , visit_start(finest + 1)
  {
    for (unsigned int l = cycle.linear_coarsest(); l <= finest; ++l)
      {
        infinite[l].reinit(hierarchy.level(l).partitioner);
        infinite[l] = std::numeric_limits<double>::infinity();
        update_ghosts(infinite[l]);
        multigrid.defect[l].reinit(hierarchy.level(l).partitioner);
      }
    // a restriction to level l - 1 starts its visits with a new defect
    multigrid.connect_restriction([this](const bool start, const unsigned int l) {
      if (!start)
        pre.new_defect(l - 1);
    });
    connect_visit_timers();
  }


  template <int dim>
  void
  LinearMultigrid<dim>::connect_visit_timers()
  {
    // a visit of level l lasts from its pre-smoothing to its
    // post-smoothing, or is the coarse solve
    auto visit = [this](const bool start, const unsigned int l) {
      const auto now = std::chrono::steady_clock::now();
      if (start)
        visit_start[l] = now;
      else
        {
          counters.level_visits[l].seconds +=
            std::chrono::duration<double>(now - visit_start[l]).count();
          ++counters.level_visits[l].calls;
        }
    };
    multigrid.connect_pre_smoother_step([visit](const bool start, const unsigned int l) {
      if (start)
        visit(true, l);
    });
    multigrid.connect_post_smoother_step([visit](const bool start, const unsigned int l) {
      if (!start)
        visit(false, l);
    });
    multigrid.connect_coarse_solve(visit);
  }


  template <int dim>
  void
  LinearMultigrid<dim>::prepare(const SparseMatrix<double> &A, const std::vector<DoFRole> &role)
  {
    cycle.update_linear_operators(A, role);
    matrices.set_fine(A);
  }


  template <int dim>
  void
  LinearMultigrid<dim>::vmult(LevelVector &dst, const LevelVector &src)
  {
    // (a V-cycle adds the restricted defects to those of the levels below)
    for (unsigned int l = multigrid.get_minlevel(); l < finest; ++l)
      multigrid.defect[l] = 0;
    multigrid.defect[finest] = src;
    pre.new_defect(finest);
    multigrid.cycle();
    dst = multigrid.solution[finest];
    // the finest level's projected smoothing outside the cycle uses the
    // obstacles, not the linear roles
    pre_smoother.use_linear_roles(finest, false);
  }

  template class LinearMultigrid<2>;
  template class LinearMultigrid<3>;
} // namespace FoslsContact
