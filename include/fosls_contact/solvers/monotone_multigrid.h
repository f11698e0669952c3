#ifndef fosls_contact_solvers_monotone_multigrid_h
#define fosls_contact_solvers_monotone_multigrid_h

#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/solvers/coarse_solver.h>
#include <fosls_contact/solvers/flux_rerouting.h>
#include <fosls_contact/solvers/level_operators.h>
#include <fosls_contact/solvers/monotone_cycle.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>
#include <fosls_contact/solvers/newton_step.h>
#include <fosls_contact/solvers/patch_smoother.h>
#include <fosls_contact/solvers/qp_solver.h>
#include <fosls_contact/solvers/solver_statistics.h>

namespace FoslsContact
{
  /**
   * The monotone multilevel method of paper sections 4.2, 5 and 6, the
   * default solver: every iteration is one plain cycle (Solver/Krylov
   * steps = 0; MonotoneCycle) or one step of truncated nonsmooth Newton
   * multigrid (NewtonStep), reported to the observer, until it says stop.
   *
   * Its parts, each in its own file:
   * - MultilevelHierarchy: the rotated prolongations, the vertex patches
   *   with their colors and the contact relations of the levels, built
   *   once per mesh;
   * - PatchSmoother (PackedPatches): the projected vertex-patch smoother;
   * - LevelOperators (GalerkinProduct, FluxRerouting): the truncated
   *   prolongations and the Galerkin operators;
   * - CoarseObstacles: the obstacles of the coarse levels;
   * - CoarseSolver: the exact solve of the coarsest level;
   * - MonotoneCycle: the cycle (and the Newton step's linear cycle);
   *   NewtonStep: the Newton step;
   * - MultigridCounters: what they count and time (statistics()).
   *
   * Distributed over the processes of the mesh, the method is the same
   * (same patch order and colors, same truncation, obstacles and coarse
   * problems): vectors are LevelVectors, the level operators local
   * matrices with the owned rows and the ghost rows of the patches, the
   * coarsest problem is gathered on every process and solved there.
   * Numbers differ between process counts only by the order of sums
   * (Galerkin products, dot products).
   */
  template <int dim>
  class MonotoneMultigrid : public QPSolver
  {
  public:
    /**
     * The set-up that depends only on the mesh and on @p fine_sparsity,
     * the pattern of the matrix of the problems to be solved (a
     * ConstrainedQP's compressed pattern): the hierarchy and the patterns
     * of the Galerkin products. On an adaptively refined
     * @p discretization solving on its finest level, the levels are
     * those of LevelMeshes (built here). Collective.
     */
    MonotoneMultigrid(const Discretization<dim> & discretization,
                      const LevelTransfer<dim> &  transfer,
                      const unsigned int          finest_level,
                      const SparsityPattern &     fine_sparsity,
                      const Parameters::Solver &  parameters);

    void solve(const ConstrainedQP &qp, LevelVector &x, IterationObserver &observer) override;

    /**
     * The wall time of the parts of solve() that are called inside the
     * cycles ("Solve: smoothing", "Solve: Galerkin operators and patch
     * setup", "Solve: coarse solve"), the patch colors, the level visits
     * and times and the coarse defect check.
     */
    SolverStatistics statistics() const override;

  private:
    /** One iteration from @p x; returns the cycles to count. */
    unsigned int iterate(const ConstrainedQP &qp, LevelVector &x);
    /** The energy increases counted so far, over all processes. */
    unsigned int energy_increases(const ConstrainedQP &qp) const;

    /** The levels of an adaptively refined mesh (empty on a uniform one). */
    const std::unique_ptr<const LevelMeshes<dim>> level_meshes;
    const MultilevelHierarchy<dim> hierarchy;
    const Parameters::Solver       parameters;
    /** The pattern the Galerkin products were set up for. */
    const SparsityPattern *        fine_sparsity;
    const unsigned int             finest;
    MultigridCounters              counters;
    PatchSmoother                  pre_smoother;
    const PatchSmoother            post_smoother;
    FluxRerouting<dim>             rerouting;
    LevelOperators<dim>            operators;
    CoarseSolver                   coarse_solver;
    MonotoneCycle<dim>             cycle;
    NewtonStep<dim>                newton_step;
  };
} // namespace FoslsContact

#endif
