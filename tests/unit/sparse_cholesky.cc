// Checks SparseCholesky, the sparse Cholesky factorization (CHOLMOD) of the
// definiteness check:
//  - a positive definite matrix (a 2D five-point Laplacian plus a shift)
//    is factorized, and each of several right-hand sides solved at once
//    satisfies A x = b to round-off;
//  - ordered on a larger pattern (the nine-point one, the extra entries
//    zero) it gives the same solutions to round-off;
//  - an indefinite matrix (the Laplacian shifted below its least
//    eigenvalue) is refused (factorize() returns false), and the same
//    object then factorizes a definite matrix again.
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/qp/sparse_cholesky.h>

#include "tests.h"

using namespace FoslsContactTests;

namespace
{
  constexpr unsigned int m = 20; // grid points per direction
  constexpr unsigned int n = m * m;

  /** The pattern of the five-point (or, @p wide, nine-point) stencil. */
  SparsityPattern
  stencil_pattern(const bool wide)
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            {
              const int a = i + di, b = j + dj;
              if (a < 0 || b < 0 || a >= static_cast<int>(m) || b >= static_cast<int>(m))
                continue;
              if (!wide && di != 0 && dj != 0)
                continue;
              dsp.add(i * m + j, a * m + b);
            }
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    return pattern;
  }

  /** The five-point Laplacian plus @p shift times the identity. */
  void
  fill_laplacian(SparseMatrix<double> &A, const double shift)
  {
    A = 0;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        {
          const unsigned int row = i * m + j;
          A.set(row, row, 4. + shift);
          if (i > 0)
            A.set(row, row - m, -1.);
          if (i + 1 < m)
            A.set(row, row + m, -1.);
          if (j > 0)
            A.set(row, row - 1, -1.);
          if (j + 1 < m)
            A.set(row, row + 1, -1.);
        }
  }

  std::vector<LevelVector>
  right_hand_sides()
  {
    std::vector<LevelVector> b(3, LevelVector(n));
    for (unsigned int i = 0; i < n; ++i)
      {
        b[0][i] = 1.;
        b[1][i] = std::sin(0.1 * i);
        b[2][i] = (i == n / 2) ? 1. : 0.;
      }
    return b;
  }

  /** max over the columns of max_i |(A x - b)_i| / max_i |b_i| */
  double
  relative_residual(const SparseMatrix<double> &     A,
                    const std::vector<LevelVector> &x,
                    const std::vector<LevelVector> &b)
  {
    double worst = 0;
    for (unsigned int k = 0; k < b.size(); ++k)
      {
        Vector<double> in(n), out(n);
        for (unsigned int i = 0; i < n; ++i)
          in[i] = x[k][i];
        A.vmult(out, in);
        double r = 0;
        for (unsigned int i = 0; i < n; ++i)
          r = std::max(r, std::abs(out[i] - b[k][i]));
        worst = std::max(worst, r / b[k].linfty_norm());
      }
    return worst;
  }
} // namespace


int
main()
{
  const SparsityPattern narrow = stencil_pattern(false), wide = stencil_pattern(true);
  SparseMatrix<double>  A(narrow);
  fill_laplacian(A, 0.01);
  const auto               b = right_hand_sides();
  std::vector<LevelVector> x(b.size(), LevelVector(n)), y = x;

  SparseCholesky cholesky;
  check(cholesky.factorize(A), "positive definite: factorized");
  cholesky.solve(x, b);
  check(relative_residual(A, x, b) < 1e-12, "three right-hand sides at once: A x = b");

  check(cholesky.factorize(A, &wide), "ordered on the nine-point pattern: factorized");
  cholesky.solve(y, b);
  double difference = 0;
  for (unsigned int k = 0; k < b.size(); ++k)
    {
      y[k] -= x[k];
      difference = std::max(difference, y[k].linfty_norm() / x[k].linfty_norm());
    }
  check(difference < 1e-12, "the same solutions on the larger pattern");

  // the least eigenvalue of the five-point Laplacian is 8 sin^2(pi / (2 (m + 1)))
  // = 0.0223 here: shifted by -0.1 it is indefinite
  fill_laplacian(A, -0.1);
  check(!cholesky.factorize(A), "indefinite: refused");

  fill_laplacian(A, 1.);
  check(cholesky.factorize(A), "a definite matrix after the refusal: factorized");
  cholesky.solve(x, b);
  check(relative_residual(A, x, b) < 1e-12, "and A x = b");
  return exit_code();
}
