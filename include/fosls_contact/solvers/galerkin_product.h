#ifndef fosls_contact_solvers_galerkin_product_h
#define fosls_contact_solvers_galerkin_product_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The Galerkin product A_H = P~^T A P~ of a truncated prolongation P~
   * (paper eqs. 34-36) on fixed sparsity patterns, row by row and in
   * parallel (deal.II's SparseMatrix::mmult and Tmmult are serial, and on
   * the finest levels the products are recomputed whenever the truncation
   * changes, which made them a fifth of the solve time at level 9).
   *
   * The product A P~ is computed by rows of A; P~^T (A P~) by rows of the
   * result, i.e. by columns of P~, for which the pattern of P~ is
   * transposed once in initialize(). Every entry is summed in a fixed
   * order, so the result does not depend on the number of threads.
   */
  class GalerkinProduct
  {
  public:
    /** Transpose the pattern of the prolongation (n_fine x n_coarse). */
    void initialize(const SparsityPattern &prolongation_pattern);

    /**
     * product = A P, galerkin = P^T product. The patterns of @p product and
     * @p galerkin must hold every entry of the products (as those of
     * DynamicSparsityPattern::compute_mmult_pattern and
     * compute_Tmmult_pattern do); @p P must have the pattern given to
     * initialize().
     */
    void compute(const SparseMatrix<double> &A,
                 const SparseMatrix<double> &P,
                 SparseMatrix<double> &      product,
                 SparseMatrix<double> &      galerkin);

    /**
     * dst = P^T src for the P of the last compute(), by columns of P in
     * parallel (SparseMatrix::Tvmult is serial: it scatters into dst).
     */
    void Tvmult(Vector<double> &dst, const Vector<double> &src) const;

  private:
    /** The values of the last P, in the order of its pattern. */
    std::vector<double>       P_values;
    /** Column j of P: entries transpose_start[j] .. transpose_start[j+1]. */
    std::vector<std::size_t>  transpose_start;
    /** Row of each entry of a column, and its position in P's storage. */
    std::vector<unsigned int> transpose_row;
    std::vector<std::size_t>  transpose_position;
    unsigned int              n_coarse = 0;
  };
} // namespace FoslsContact

#endif
