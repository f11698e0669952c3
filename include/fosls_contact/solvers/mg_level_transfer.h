#ifndef fosls_contact_solvers_mg_level_transfer_h
#define fosls_contact_solvers_mg_level_transfer_h

#include <deal.II/multigrid/mg_base.h>

#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/solvers/level_operators.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>

#include <vector>

namespace FoslsContact
{
  /**
   * The transfer of the linear truncated cycle as deal.II's
   * MGTransferBase: prolongation by the truncated prolongation P~ of
   * LevelOperators, restriction by its transpose.
   *
   * P~ is LevelTransfer's prolongation (sign-correct for the RT
   * functions, which MGTransferPrebuilt of deal.II 9.4 is not on the half
   * disc) with the rows of the truncated fine DoFs zeroed and the coarse
   * faces with a truncated son removed, exactly the transfer of the own
   * linear cycle (MonotoneCycle), so that a truncated DoF neither receives
   * a coarse correction nor passes on its defect. It is read from
   * LevelOperators at every call, so it follows the truncation that
   * MonotoneCycle::update_linear_operators() set.
   */
  template <int dim>
  class MGLevelTransfer : public MGTransferBase<LevelVector>
  {
  public:
    MGLevelTransfer(const MultilevelHierarchy<dim> &hierarchy,
                    const LevelOperators<dim> &     operators);

    /** dst = P~ src (owned entries of @p dst). Collective. */
    void prolongate(const unsigned int to_level,
                    LevelVector &      dst,
                    const LevelVector &src) const override;
    /** dst += P~ src (owned entries of @p dst). Collective. */
    void prolongate_and_add(const unsigned int to_level,
                            LevelVector &      dst,
                            const LevelVector &src) const override;
    /** dst += P~^T src (owned entries). Collective. */
    void restrict_and_add(const unsigned int from_level,
                          LevelVector &      dst,
                          const LevelVector &src) const override;

  private:
    /** The work vector of level @p l, set up on first use. */
    LevelVector &work(const unsigned int l) const;

    const MultilevelHierarchy<dim> &hierarchy;
    const LevelOperators<dim> &     operators;
    /**
     * Work vectors per level: a cycle transfers hundreds of times per
     * Newton step, too often to allocate a vector each time.
     */
    mutable std::vector<LevelVector> work_vectors;
  };
} // namespace FoslsContact

#endif
