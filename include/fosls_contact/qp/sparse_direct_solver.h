#ifndef fosls_contact_qp_sparse_direct_solver_h
#define fosls_contact_qp_sparse_direct_solver_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fosls_contact/qp/level_algebra.h>

#include <memory>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace FoslsContact
{
  using namespace dealii;

  /**
   * A sparse direct solver for the reference solver (the active set
   * method and its cross checks): Trilinos Amesos with KLU, an LU
   * factorization with pivoting. On these FOSLS matrices KLU factorizes
   * several times faster than UMFPACK (doc/performance.md, "Figures behind the code"), so it is the
   * fairer reference. On several processes
   * the matrix is a distributed Trilinos matrix; Amesos gathers it on one
   * process to factorize it (KLU is serial), which limits the reference
   * solver, not the multigrid method, to what one process can hold.
   */
  class SparseDirectSolver
  {
  public:
    SparseDirectSolver();
    /**
     * Factorize the local matrix @p matrix (its owned rows, columns in the
     * local indices of @p partitioner), on @p pattern (which must hold the
     * matrix's pattern) if given: KLU's fill-reducing ordering (AMD) works
     * on the pattern, and does far better on the DoF coupling pattern of
     * the mesh than on the pattern of a ConstrainedQP's matrix, from which
     * zero and round-off entries are gone (an active set solve many times
     * as fast; doc/performance.md, "Figures behind the code").
     * Collective.
     */
    void initialize(const SparseMatrix<double> &                               matrix,
                    const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                    const SparsityPattern *                                    pattern = nullptr);
    /** x = A^{-1} b (owned entries) with the factorization of initialize(). */
    void vmult(LevelVector &x, const LevelVector &b) const;
    /**
     * x[k] = A^{-1} b[k] for all k, in one call of the direct solver: KLU
     * then reads its factors once for all columns instead of once per
     * column (the definiteness check solves once per contact DoF, in
     * blocks). Each column gets the same result as vmult() of it alone.
     * Collective.
     */
    void vmult(std::vector<LevelVector> &x, const std::vector<LevelVector> &b) const;

    ~SparseDirectSolver();

  private:
    /** *x[k] = A^{-1} *b[k]: the owned entries through Epetra's vectors. */
    void solve(const std::vector<LevelVector *> &x, const std::vector<const LevelVector *> &b) const;

    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
    std::unique_ptr<TrilinosWrappers::SparseMatrix>    matrix;
    std::unique_ptr<Epetra_LinearProblem>              problem;
    std::unique_ptr<Amesos_BaseSolver>                 solver;
  };
} // namespace FoslsContact

#endif
