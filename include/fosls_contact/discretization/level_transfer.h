#ifndef fosls_contact_discretization_level_transfer_h
#define fosls_contact_discretization_level_transfer_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/qp/matrix_list_memory.h>

#include <memory>

namespace FoslsContact
{
  /**
   * The prolongations P_{l-1}^{l} of eqs. (15)-(16) between consecutive
   * levels, in Cartesian coordinates, as sparse matrices.
   *
   * They are assembled exactly as MGTransferPrebuilt::build() does, from
   * the FESystem's embedding matrices (nodal interpolation for Q1, normal
   * flux preservation for RT0), entry by entry with `set`. We build them
   * ourselves because MGTransferPrebuilt keeps its matrices private and the
   * monotone method needs their entries (truncation, Galerkin products),
   * and because on meshes whose cells are not aligned the RT shape
   * functions carry sign flips that the reference embedding must be
   * corrected for (MGTransferPrebuilt of deal.II 9.4 ignores them). The
   * test tests/unit/level_transfer checks that a coarse function and its
   * prolongation agree point by point.
   *
   * On a distributed mesh each process has the rows of all its local fine
   * DoFs (owned and ghost): every cell here has its parent here, and the
   * columns are local coarse DoFs.
   */
  template <int dim>
  class LevelTransfer
  {
  public:
    explicit LevelTransfer(const Discretization<dim> &discretization);

    /**
     * Prolongation from level @p to_level - 1 to level @p to_level (local
     * matrix: local fine rows, local coarse columns).
     */
    const SparseMatrix<double> &prolongation(const unsigned int to_level) const
    {
      return *matrices[to_level];
    }

    /** dst = P src (owned entries of @p dst), Cartesian coordinates. */
    void prolongate(const unsigned int to_level,
                    LevelVector &      dst,
                    const LevelVector &src) const;

    /** The bytes of the prolongation matrices and their patterns, by level. */
    LevelBytes memory_consumption() const;

  private:
    std::vector<std::unique_ptr<SparsityPattern>>      sparsities;
    std::vector<std::unique_ptr<SparseMatrix<double>>> matrices;
  };
} // namespace FoslsContact

#endif
