#ifndef fosls_contact_solvers_galerkin_product_h
#define fosls_contact_solvers_galerkin_product_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/qp/level_algebra.h>

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
   * The product A P~ is not stored: it would be the largest matrix of the
   * multigrid after the patch smoothers (a fine row of A P~ reaches the
   * coarse functions of all cells around the row's DoF). compute() takes
   * the owned fine rows in blocks of block_rows: it computes the rows of
   * A P~ of a block in parallel into a buffer, then adds their part of
   * P~^T (A P~) to every coarse row they reach, in parallel over those
   * rows, for which the pattern of P~ is transposed once in initialize().
   * Every entry of the result is thus the sum over its fine rows in
   * increasing order, each term p_rj (A P~)_rc computed as a whole row of
   * A P~ would be: the result does not depend on the number of threads
   * or on the blocks. A coarse row this process does not own gets only
   * part of its sum here; the parts go to the row's owner, which adds them
   * to its own part in the order of the sending processes (with several
   * processes, the partition fixes the order of the parts).
   *
   * The coarse operator is stored on the coupling pattern of the coarse
   * level's cells (AlgebraicLevel::sparsity): a coarse basis function
   * prolongates to fine functions inside the coarse cells at its DoF, so
   * two coarse DoFs that share no coarse cell have an exact zero (checked:
   * a nonzero outside that pattern is an error).
   */
  class GalerkinProduct
  {
  public:
    /**
     * Set up the patterns: @p prolongation_pattern has the local fine rows
     * and local coarse columns of P~, @p fine_pattern the rows of A (the
     * owned rows are used), @p coarse_pattern is the pattern of the result.
     * Collective.
     */
    void initialize(const SparsityPattern &                                    prolongation_pattern,
                    const SparsityPattern &                                    fine_pattern,
                    const std::shared_ptr<const Utilities::MPI::Partitioner> &fine_partitioner,
                    const SparsityPattern &                                    coarse_pattern,
                    const std::shared_ptr<const Utilities::MPI::Partitioner> &coarse_partitioner);

    /**
     * galerkin = P^T A P on the owned rows of @p galerkin (its ghost rows
     * are left alone). @p A and @p P must be on the patterns given to
     * initialize(). Collective.
     */
    void compute(const SparseMatrix<double> &A,
                 const SparseMatrix<double> &P,
                 SparseMatrix<double> &      galerkin);

    /**
     * dst = P^T src (owned entries of @p dst) for the P of the last
     * compute(), by columns of P in parallel. Collective.
     */
    void Tvmult(LevelVector &dst, const LevelVector &src) const;

    /** The bytes of the index arrays (A P is not kept, see the class). */
    std::size_t memory_consumption() const;

  private:
    /** transpose_start, transpose_row and transpose_position of @p pattern. */
    void transpose_pattern(const SparsityPattern &pattern, const unsigned int n_owned);
    /** send_to and receive_from. Collective. */
    void set_up_ghost_messages(const Utilities::MPI::Partitioner &coarse_partitioner,
                               const SparsityPattern &            coarse_pattern);
    /**
     * Send the parts of the ghost rows to their owners and add the parts
     * of the others to the owned rows of @p galerkin. Collective.
     */
    void add_ghost_parts(SparseMatrix<double> &galerkin);

    /** A thread's work arrays and compute()'s state (galerkin_product.cc). */
    struct ProductWork;
    struct ProductState;
    /**
     * The rows r0 .. r1 of A P into @p state's block buffer, in parallel:
     * the product is computed a block at a time so that it never has to be
     * stored whole (see the class).
     */
    void multiply_block(const SparseMatrix<double> &A,
                        const SparseMatrix<double> &P,
                        const unsigned int          r0,
                        const unsigned int          r1,
                        ProductState &              state) const;
    /**
     * The block's part of P^T (A P) added to every coarse row it reaches,
     * in parallel over those rows: each row's sums are loaded, continued
     * over the block's fine rows in increasing order and stored back, so
     * that every entry is the same sum whatever the blocks and threads.
     */
    void add_block(const SparseMatrix<double> &P,
                   const unsigned int          r0,
                   const unsigned int          r1,
                   SparseMatrix<double> &      galerkin,
                   ProductState &              state);
    /**
     * The partial sums of coarse row @p j into (@p load) or out of the dense
     * @p row, which is left zero: an owned row's entries in @p galerkin and
     * its @p extra_values outside the pattern, or a ghost row's parts.
     */
    void move_sums(const unsigned int    j,
                   std::vector<double> & row,
                   const bool            load,
                   SparseMatrix<double> &galerkin,
                   std::vector<double> & extra_values);

    /** The values of the last P, in the order of its pattern. */
    std::vector<double>       P_values;
    /**
     * Column j of the owned rows of P: entries transpose_start[j] ..
     * transpose_start[j+1].
     */
    std::vector<std::size_t>  transpose_start;
    /** Row of each entry of a column, and its position in P's storage. */
    std::vector<unsigned int> transpose_row;
    std::vector<std::size_t>  transpose_position;
    /**
     * For every owned coarse row, the columns the product can reach that
     * are not in the result's pattern (extra_columns[extra_start[j] ..
     * extra_start[j+1]]): their sums must be exact zeros (checked).
     */
    std::vector<std::size_t>  extra_start;
    std::vector<unsigned int> extra_columns;
    /**
     * The number of entries of every owned fine row of A P on the patterns
     * (at most that many are nonzero): the room of a row in compute()'s
     * buffer.
     */
    std::vector<unsigned int> product_row_length;
    unsigned int              n_coarse_local = 0, n_coarse_owned = 0;

    /**
     * The parts of the ghost coarse rows: for every such row, the local
     * coarse columns it can get (ghost_columns[ghost_start[r] ..
     * ghost_start[r+1]]), and per owner process the rows it gets.
     */
    std::vector<unsigned int>  ghost_row;
    std::vector<std::size_t>   ghost_start;
    std::vector<unsigned int>  ghost_columns;
    std::vector<double>        ghost_values;
    /** Per process: its rank and the ranges of ghost rows it owns. */
    std::vector<std::pair<unsigned int, std::pair<unsigned int, unsigned int>>> send_to;
    /**
     * Per process sending parts of rows owned here: its rank and, for each
     * value it sends, the local (row, column), or an invalid row where the
     * entry is outside the pattern (the value must be 0).
     */
    std::vector<std::pair<unsigned int, std::vector<std::pair<unsigned int, unsigned int>>>>
             receive_from;
    MPI_Comm comm = MPI_COMM_SELF;
  };
} // namespace FoslsContact

#endif
