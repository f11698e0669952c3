#ifndef fosls_contact_qp_product_pattern_h
#define fosls_contact_qp_product_pattern_h

#include <deal.II/lac/sparsity_pattern.h>

#include <cstddef>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The columns of the rows of a sparse matrix product A B: row i's are
   * `columns[start[i]]` up to `columns[start[i + 1]]`, sorted. These are the
   * columns DynamicSparsityPattern::compute_mmult_pattern() gives, but
   * gathered with one mark per column (the last row that took it) instead
   * of a search of the row for every candidate: a row of A B has as many
   * candidates as products of A's entries with B's rows, mostly repeated,
   * and those searches, with a memory block per row, took most of the
   * Galerkin products' and the rotated prolongations' set-up on the
   * square's finest level.
   */
  struct ProductPattern
  {
    /** The rows 0 to @p n_rows - 1 of A B, for the patterns of A and B. */
    ProductPattern(const SparsityPattern &a, const SparsityPattern &b, unsigned int n_rows);

    unsigned int
    row_length(const unsigned int i) const
    {
      return start[i + 1] - start[i];
    }

    /**
     * Make @p pattern the product's rows built here, compressed. A square
     * SparsityPattern also keeps the diagonal, as SparseMatrix::mmult()'s
     * own does.
     */
    void
    fill(SparsityPattern &pattern, unsigned int n_columns) const;

    std::vector<std::size_t>  start;
    std::vector<unsigned int> columns;
  };
} // namespace FoslsContact

#endif
