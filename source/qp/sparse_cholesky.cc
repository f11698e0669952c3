#include <fosls_contact/qp/sparse_cholesky.h>

#include <cholmod.h>

namespace FoslsContact
{
  struct SparseCholesky::Data
  {
    Data()
    {
      cholmod_start(&common);
      // Always the supernodal L L^T: a positive pivot at every column is
      // the test of definiteness. (CHOLMOD's simplicial L D L^T, its
      // choice for small or very sparse matrices, factorizes indefinite
      // matrices too.)
      common.supernodal = CHOLMOD_SUPERNODAL;
      // (a refusal is reported by factorize(), not printed by CHOLMOD)
      common.print = 0;
    }
    ~Data()
    {
      if (factor)
        cholmod_free_factor(&factor, &common);
      cholmod_finish(&common);
    }
    cholmod_common  common;
    cholmod_factor *factor = nullptr;
  };


  SparseCholesky::SparseCholesky()
    : data(std::make_unique<Data>())
  {}


  SparseCholesky::~SparseCholesky() = default;


  bool
  SparseCholesky::factorize(const SparseMatrix<double> &matrix, const SparsityPattern *pattern)
  {
    AssertThrow(matrix.m() == matrix.n(), ExcDimensionMismatch(matrix.m(), matrix.n()));
    n                                = matrix.m();
    const SparsityPattern &structure = pattern ? *pattern : matrix.get_sparsity_pattern();
    AssertThrow(structure.n_rows() == n && structure.n_cols() == n,
                ExcDimensionMismatch(structure.n_rows(), n));
    cholmod_common &       common    = data->common;
    if (data->factor)
      cholmod_free_factor(&data->factor, &common);

    // The lower triangle by columns (CHOLMOD's stype -1): row i's entries
    // right of the diagonal are column i's below it, the matrix being
    // symmetric. (deal.II keeps a row's diagonal first, the other columns
    // sorted after it.)
    std::size_t n_entries = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (auto e = structure.begin(i); e != structure.end(i); ++e)
        n_entries += e->column() >= i;
    cholmod_sparse *A =
      cholmod_allocate_sparse(n, n, n_entries, /*sorted*/ 1, /*packed*/ 1, /*stype*/ -1,
                              CHOLMOD_REAL, &common);
    AssertThrow(A, ExcMessage("CHOLMOD could not allocate a matrix of " + std::to_string(n) +
                              " rows and " + std::to_string(n_entries) + " entries"));
    auto *const column_start = static_cast<int *>(A->p);
    auto *const row          = static_cast<int *>(A->i);
    auto *const value        = static_cast<double *>(A->x);
    std::size_t k            = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        column_start[i] = k;
        for (auto e = structure.begin(i); e != structure.end(i); ++e)
          if (e->column() >= i)
            {
              row[k]   = e->column();
              value[k] = matrix.el(i, e->column());
              ++k;
            }
        // (the diagonal came first: the column's other rows follow sorted)
      }
    column_start[n] = k;

    data->factor = cholmod_analyze(A, &common);
    if (data->factor != nullptr)
      cholmod_factorize(A, data->factor, &common);
    cholmod_free_sparse(&A, &common);
    // (an error is negative; a matrix that is not positive definite is
    // CHOLMOD's warning CHOLMOD_NOT_POSDEF, with the failed column in minor)
    if (data->factor == nullptr || common.status < CHOLMOD_OK)
      {
        const int status = common.status;
        if (data->factor)
          cholmod_free_factor(&data->factor, &common);
        AssertThrow(false,
                    ExcMessage("CHOLMOD could not factorize a matrix of " + std::to_string(n) +
                               " rows (" +
                               (status == CHOLMOD_OUT_OF_MEMORY ? "out of memory" :
                                status == CHOLMOD_TOO_LARGE     ? "too large for its int indices" :
                                                                  "status " + std::to_string(status)) +
                               ")"));
      }
    if (common.status == CHOLMOD_NOT_POSDEF || data->factor->minor < n)
      {
        cholmod_free_factor(&data->factor, &common);
        return false;
      }
    return true;
  }


  void
  SparseCholesky::solve(std::vector<LevelVector> &x, const std::vector<LevelVector> &b) const
  {
    Assert(data->factor, ExcMessage("SparseCholesky: no factor (factorize() first)"));
    AssertThrow(x.size() == b.size(), ExcDimensionMismatch(x.size(), b.size()));
    if (b.empty())
      return;
    cholmod_common &common = data->common;
    cholmod_dense * B      = cholmod_allocate_dense(n, b.size(), n, CHOLMOD_REAL, &common);
    AssertThrow(B, ExcMessage("CHOLMOD could not allocate the right-hand sides"));
    auto *const values = static_cast<double *>(B->x);
    for (std::size_t c = 0; c < b.size(); ++c)
      for (unsigned int i = 0; i < n; ++i)
        values[c * n + i] = b[c].local_element(i);
    cholmod_dense *X = cholmod_solve(CHOLMOD_A, data->factor, B, &common);
    cholmod_free_dense(&B, &common);
    AssertThrow(X, ExcMessage("CHOLMOD could not solve with its factor"));
    const auto *const solution = static_cast<const double *>(X->x);
    for (std::size_t c = 0; c < x.size(); ++c)
      for (unsigned int i = 0; i < n; ++i)
        x[c].local_element(i) = solution[c * n + i];
    cholmod_free_dense(&X, &common);
  }
} // namespace FoslsContact
