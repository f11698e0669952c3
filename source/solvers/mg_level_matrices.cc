#include <fosls_contact/solvers/mg_level_matrices.h>

namespace FoslsContact
{
  template <int dim>
  MGLevelMatrices<dim>::MGLevelMatrices(const MultilevelHierarchy<dim> &hierarchy,
                                        const LevelOperators<dim> &     operators,
                                        const unsigned int              min_level)
    : hierarchy(hierarchy)
    , operators(operators)
    , min_level(min_level)
    , finest(hierarchy.finest_level())
    , work(finest + 1)
  {}


  template <int dim>
  const SparseMatrix<double> &
  MGLevelMatrices<dim>::matrix(const unsigned int level) const
  {
    Assert(level < finest || fine != nullptr, ExcMessage("no finest operator set"));
    return level == finest ? *fine : operators.galerkin(level);
  }


  template <int dim>
  void
  MGLevelMatrices<dim>::vmult(const unsigned int level,
                              LevelVector &      dst,
                              const LevelVector &src) const
  {
    FoslsContact::vmult(matrix(level), dst, src);
  }


  template <int dim>
  void
  MGLevelMatrices<dim>::vmult_add(const unsigned int level,
                                  LevelVector &      dst,
                                  const LevelVector &src) const
  {
    if (work[level].get_partitioner() != hierarchy.level(level).partitioner)
      work[level].reinit(hierarchy.level(level).partitioner);
    vmult(level, work[level], src);
    dst += work[level];
  }

  template class MGLevelMatrices<2>;
  template class MGLevelMatrices<3>;
} // namespace FoslsContact
