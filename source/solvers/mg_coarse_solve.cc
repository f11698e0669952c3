#include <fosls_contact/solvers/mg_coarse_solve.h>

namespace FoslsContact
{
  template <int dim>
  MGCoarseSolve<dim>::MGCoarseSolve(const MultilevelHierarchy<dim> &hierarchy,
                                    const LevelOperators<dim> &     operators,
                                    CoarseSolver &                  coarse_solver,
                                    const std::vector<LevelVector> &infinite)
    : hierarchy(hierarchy)
    , operators(operators)
    , coarse_solver(coarse_solver)
    , infinite(infinite)
  {}


  template <int dim>
  void
  MGCoarseSolve<dim>::operator()(const unsigned int level,
                                 LevelVector &      dst,
                                 const LevelVector &src) const
  {
    const SparseMatrix<double> &A = operators.galerkin(level);
    dst                           = 0;
    // (the level's partitioner, not dst's: every process takes part)
    coarse_solver.solve(*hierarchy.level(level).partitioner,
                        A,
                        operators.version_of(level, A).second,
                        src,
                        infinite[level],
                        hierarchy.level(level).role,
                        dst);
  }

  template class MGCoarseSolve<2>;
  template class MGCoarseSolve<3>;
} // namespace FoslsContact
