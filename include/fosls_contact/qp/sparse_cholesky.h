#ifndef fosls_contact_qp_sparse_cholesky_h
#define fosls_contact_qp_sparse_cholesky_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/qp/level_algebra.h>

#include <memory>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * A sparse Cholesky factorization, A = L L^T, of a symmetric positive
   * definite matrix held by one process: SuiteSparse's CHOLMOD (which
   * deal.II's own dependencies bring), supernodal, with its fill-reducing
   * ordering (AMD, or METIS's nested dissection where that fills less).
   *
   * The definiteness check factorizes A_II, the functional's matrix
   * without its contact and fixed DoFs, which is positive definite
   * whenever the problem is well posed (doc/method.md section 6). A
   * Cholesky factorization needs no pivoting and works on dense blocks of
   * columns: the check takes a third of the time it takes with KLU's LU
   * (Amesos, the reference solver's factorization) on the cube's level 4,
   * the level the cube's checks run on from level 5 up, and far less on
   * finer levels (bench/definiteness_cost.py, doc/performance.md, section
   * 6).
   */
  class SparseCholesky
  {
  public:
    SparseCholesky();
    ~SparseCholesky();
    SparseCholesky(const SparseCholesky &) = delete;
    SparseCholesky &operator=(const SparseCholesky &) = delete;

    /**
     * Factorize @p matrix (square, all rows here; its lower triangle is
     * read, the upper one is the same by symmetry), ordered on @p pattern
     * if given (which must hold the matrix's pattern; as for
     * SparseDirectSolver, the mesh's coupling pattern orders better than
     * the pattern of a matrix whose zeros are gone). Returns false,
     * keeping no factor, if the matrix is not positive definite in
     * floating point.
     */
    bool factorize(const SparseMatrix<double> &matrix, const SparsityPattern *pattern = nullptr);

    /** x[k] = A^{-1} b[k] for all k, in one solve with all columns. */
    void solve(std::vector<LevelVector> &x, const std::vector<LevelVector> &b) const;

  private:
    /** CHOLMOD's workspace and the factor (cholmod_common, cholmod_factor). */
    struct Data;
    std::unique_ptr<Data> data;
    unsigned int          n = 0;
  };
} // namespace FoslsContact

#endif
