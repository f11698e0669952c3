#ifndef fosls_contact_solvers_mg_level_matrices_h
#define fosls_contact_solvers_mg_level_matrices_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/multigrid/mg_base.h>

#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/solvers/level_operators.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>

#include <vector>

namespace FoslsContact
{
  /**
   * The operators of the linear truncated cycle as deal.II's
   * MGMatrixBase: the finest level's matrix (set_fine()) and, below it,
   * the Galerkin operators P~^T A P~ of LevelOperators. The finest matrix
   * is not truncated: the cycle's iterate stays zero at the fixed DoFs
   * (the smoother does not move them, P~ has no rows for them), and the
   * restriction drops their defect. All operators are symmetric, so
   * Tvmult is vmult.
   */
  template <int dim>
  class MGLevelMatrices : public MGMatrixBase<LevelVector>
  {
  public:
    /** The levels @p min_level .. finest of @p hierarchy. */
    MGLevelMatrices(const MultilevelHierarchy<dim> &hierarchy,
                    const LevelOperators<dim> &     operators,
                    const unsigned int              min_level);

    /** The finest level's operator is @p A. */
    void set_fine(const SparseMatrix<double> &A) { fine = &A; }

    /** The operator of level @p level. */
    const SparseMatrix<double> &matrix(const unsigned int level) const;

    /** dst = A_level src (owned entries of @p dst). Collective. */
    void vmult(const unsigned int level, LevelVector &dst, const LevelVector &src) const override;
    /** dst += A_level src. Collective. */
    void vmult_add(const unsigned int level,
                   LevelVector &      dst,
                   const LevelVector &src) const override;
    void Tvmult(const unsigned int level, LevelVector &dst, const LevelVector &src) const override
    {
      vmult(level, dst, src);
    }
    void Tvmult_add(const unsigned int level,
                    LevelVector &      dst,
                    const LevelVector &src) const override
    {
      vmult_add(level, dst, src);
    }
    unsigned int get_minlevel() const override { return min_level; }
    unsigned int get_maxlevel() const override { return finest; }

  private:
    const MultilevelHierarchy<dim> &hierarchy;
    const LevelOperators<dim> &     operators;
    const unsigned int              min_level, finest;
    const SparseMatrix<double> *    fine = nullptr;
    /** Work vectors of vmult_add() per level (set up on first use). */
    mutable std::vector<LevelVector> work;
  };
} // namespace FoslsContact

#endif
