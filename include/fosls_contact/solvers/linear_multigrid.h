#ifndef fosls_contact_solvers_linear_multigrid_h
#define fosls_contact_solvers_linear_multigrid_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/multigrid/multigrid.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/dof_role.h>
#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/solvers/coarse_solver.h>
#include <fosls_contact/solvers/level_operators.h>
#include <fosls_contact/solvers/mg_coarse_solve.h>
#include <fosls_contact/solvers/mg_level_matrices.h>
#include <fosls_contact/solvers/mg_level_transfer.h>
#include <fosls_contact/solvers/mg_patch_smoother.h>
#include <fosls_contact/solvers/monotone_cycle.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>
#include <fosls_contact/solvers/patch_smoother.h>
#include <fosls_contact/solvers/solver_statistics.h>

#include <chrono>
#include <vector>

namespace FoslsContact
{
  /**
   * The Newton step's linear truncated cycle (Solver/Linear cycle =
   * deal.II) run by deal.II's Multigrid from the program's building
   * blocks: the patch smoother as its MGSmoother (MGPatchSmoother), the
   * sign-correct truncated prolongation as its MGTransferBase
   * (MGLevelTransfer), the truncated Galerkin operators as its
   * MGMatrixBase (MGLevelMatrices) and the exact solve of the linear
   * cycle's coarsest level as its MGCoarseGridBase (MGCoarseSolve). It is
   * the same cycle as MonotoneCycle's linear one (the same levels, visits,
   * sweeps and operators), so the Newton step takes the same iterates up
   * to round-off.
   *
   * The truncation and the operators are those of MonotoneCycle (a
   * Galerkin operator depends on the truncation of every finer level,
   * which LevelOperators keeps for both cycles): prepare() brings them up
   * to date for the linear roles before a linear solve.
   */
  template <int dim>
  class LinearMultigrid
  {
  public:
    /**
     * The cycle on @p hierarchy's levels from @p cycle's linear coarsest
     * level to the finest, of the type of @p parameters (V, W, F), with
     * the patch smoothers @p pre_smoother and @p post_smoother, the
     * operators of @p operators and the exact solves of @p coarse_solver;
     * the time of its level visits goes to @p counters.
     */
    LinearMultigrid(const MultilevelHierarchy<dim> &hierarchy,
                    const Parameters::Solver &      parameters,
                    PatchSmoother &                 pre_smoother,
                    const PatchSmoother &           post_smoother,
                    MonotoneCycle<dim> &            cycle,
                    LevelOperators<dim> &           operators,
                    CoarseSolver &                  coarse_solver,
                    MultigridCounters &             counters);

    /**
     * The finest level's operator is @p A and the linear roles are
     * @p role (set in the patch smoother already): truncation, Galerkin
     * operators and patch smoothers of the levels below. Collective.
     */
    void prepare(const SparseMatrix<double> &A, const std::vector<DoFRole> &role);

    /** dst = one cycle from zero for the right-hand side @p src. Collective. */
    void vmult(LevelVector &dst, const LevelVector &src);

  private:
    /** Time the level visits as MonotoneCycle does (MultigridCounters::level_visits). */
    void connect_visit_timers();

    PatchSmoother &     pre_smoother;
    MonotoneCycle<dim> &cycle;
    MultigridCounters & counters;
    const unsigned int  finest;
    /** The obstacles +inf of every level, with ghost values. */
    std::vector<LevelVector> infinite;
    MGLevelTransfer<dim>     transfer;
    MGLevelMatrices<dim>     matrices;
    MGPatchSmoother          pre, post;
    MGCoarseSolve<dim>       coarse;
    /** (after the parts it points to, so that it is destroyed first) */
    Multigrid<LevelVector> multigrid;
    std::vector<std::chrono::steady_clock::time_point> visit_start;
  };
} // namespace FoslsContact

#endif
