#ifndef fosls_contact_solvers_mg_coarse_solve_h
#define fosls_contact_solvers_mg_coarse_solve_h

#include <deal.II/multigrid/mg_base.h>

#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/solvers/coarse_solver.h>
#include <fosls_contact/solvers/level_operators.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>

namespace FoslsContact
{
  /**
   * The exact solve of the linear truncated cycle's coarsest level
   * (MonotoneCycle::linear_coarsest()) as deal.II's MGCoarseGridBase: the
   * CoarseSolver with the level's Galerkin operator, its roles and the
   * obstacles +inf, from zero (the DoFs it keeps fixed stay zero, as in
   * the own cycle, whose coarse corrections start from zero).
   */
  template <int dim>
  class MGCoarseSolve : public MGCoarseGridBase<LevelVector>
  {
  public:
    MGCoarseSolve(const MultilevelHierarchy<dim> &hierarchy,
                  const LevelOperators<dim> &     operators,
                  CoarseSolver &                  coarse_solver,
                  const std::vector<LevelVector> &infinite);

    /** dst = the solution on level @p level for the right-hand side @p src. Collective. */
    void operator()(const unsigned int level, LevelVector &dst, const LevelVector &src) const override;

  private:
    const MultilevelHierarchy<dim> &hierarchy;
    const LevelOperators<dim> &     operators;
    CoarseSolver &                  coarse_solver;
    const std::vector<LevelVector> &infinite;
  };
} // namespace FoslsContact

#endif
