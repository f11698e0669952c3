#include <fosls_contact/solvers/mg_level_transfer.h>

namespace FoslsContact
{
  template <int dim>
  MGLevelTransfer<dim>::MGLevelTransfer(const MultilevelHierarchy<dim> &hierarchy,
                                        const LevelOperators<dim> &     operators)
    : hierarchy(hierarchy)
    , operators(operators)
    , work_vectors(hierarchy.finest_level() + 1)
  {}


  template <int dim>
  LevelVector &
  MGLevelTransfer<dim>::work(const unsigned int l) const
  {
    // (a process may own no DoF of a level: the partitioner, not the
    // size, tells whether the vector is set up)
    if (work_vectors[l].get_partitioner() != hierarchy.level(l).partitioner)
      work_vectors[l].reinit(hierarchy.level(l).partitioner);
    return work_vectors[l];
  }


  template <int dim>
  void
  MGLevelTransfer<dim>::prolongate(const unsigned int to_level,
                                   LevelVector &      dst,
                                   const LevelVector &src) const
  {
    vmult(operators.truncated_prolongation(to_level), dst, src);
  }


  template <int dim>
  void
  MGLevelTransfer<dim>::prolongate_and_add(const unsigned int to_level,
                                           LevelVector &      dst,
                                           const LevelVector &src) const
  {
    LevelVector &prolongated = work(to_level);
    prolongate(to_level, prolongated, src);
    dst += prolongated;
  }


  template <int dim>
  void
  MGLevelTransfer<dim>::restrict_and_add(const unsigned int from_level,
                                         LevelVector &      dst,
                                         const LevelVector &src) const
  {
    operators.restrict_and_add(from_level, dst, src, work(from_level - 1));
  }

  template class MGLevelTransfer<2>;
  template class MGLevelTransfer<3>;
} // namespace FoslsContact
