// Checks invert_spd() on a patch matrix of the smoother on a mesh whose
// cells differ much in size: tests/unit/spd_inverse.patch is the matrix of
// a 19-DoF vertex patch on the finest level of prm/quarter_ball_file.prm
// refined to 4 levels (3D, cells differing in size by a factor 15),
// written with 17 digits. Printed: its diagonal spans 4e-3 to 4e10, and
// scaled to a unit diagonal its condition number is 1.3e9.
//  - the inverse is exactly symmetric (both triangles are filled: the
//    smoother reads the upper one, BoxQP all of it);
//  - it is positive definite: scaled by diag(M)^(1/2) on both sides its
//    smallest eigenvalue is > 0, and g^T M^{-1} g > 0 for 1000
//    pseudo-random g;
//  - M M^{-1} g = g to 1e-4 relative for those g.
// That the former inverse (Gauss-Jordan elimination) made the cycle raise
// J on this mesh is shown by tests/solver/ill_conditioned_patches.
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/solvers/spd_inverse.h>

#include "tests.h"

#include <fstream>

using namespace FoslsContactTests;

int
main()
{
  std::ifstream       in(std::string(FOSLS_SOURCE_DIR) + "/tests/unit/spd_inverse.patch");
  std::vector<double> values;
  for (double v; in >> v;)
    values.push_back(v);
  const unsigned int n = std::lround(std::sqrt(values.size()));
  check(n == 19 && n * n == values.size(), "read the 19 x 19 patch matrix");
  FullMatrix<double> M(n, n);
  for (unsigned int a = 0; a < n; ++a)
    for (unsigned int b = 0; b < n; ++b)
      M(a, b) = values[a * n + b];

  // the figures doc/method.md quotes: the span of the diagonal and the
  // condition number of M scaled to a unit diagonal
  double                   smallest_diagonal = M(0, 0), largest_diagonal = M(0, 0);
  LAPACKFullMatrix<double> scaled(n, n);
  for (unsigned int a = 0; a < n; ++a)
    {
      smallest_diagonal = std::min(smallest_diagonal, M(a, a));
      largest_diagonal  = std::max(largest_diagonal, M(a, a));
      for (unsigned int b = 0; b < n; ++b)
        scaled(a, b) = M(a, b) / std::sqrt(M(a, a) * M(b, b));
    }
  scaled.compute_eigenvalues();
  double scaled_min = std::numeric_limits<double>::infinity(), scaled_max = 0;
  for (unsigned int a = 0; a < n; ++a)
    {
      scaled_min = std::min(scaled_min, scaled.eigenvalue(a).real());
      scaled_max = std::max(scaled_max, scaled.eigenvalue(a).real());
    }
  std::cout << "diagonal from " << rounded(smallest_diagonal, 1) << " to "
            << rounded(largest_diagonal, 1) << ", condition number scaled to a unit diagonal "
            << rounded(scaled_max / scaled_min, 2) << std::endl;

  FullMatrix<double> X = M;
  invert_spd(X);

  bool symmetric = true;
  for (unsigned int a = 0; a < n; ++a)
    for (unsigned int b = 0; b < n; ++b)
      symmetric &= X(a, b) == X(b, a);
  check(symmetric, "the inverse is exactly symmetric");

  // (the eigenvalues of D X D, D = diag(M)^(1/2): M's diagonal spans 13
  // orders of magnitude, and X's own eigenvalues cannot be computed to
  // the accuracy of its smallest one)
  LAPACKFullMatrix<double> eigen(n, n);
  for (unsigned int a = 0; a < n; ++a)
    for (unsigned int b = 0; b < n; ++b)
      eigen(a, b) = std::sqrt(M(a, a)) * X(a, b) * std::sqrt(M(b, b));
  eigen.compute_eigenvalues();
  double smallest = std::numeric_limits<double>::infinity();
  for (unsigned int a = 0; a < n; ++a)
    smallest = std::min(smallest, eigen.eigenvalue(a).real());
  check(smallest > 0., "the inverse scaled by diag(M)^(1/2) has positive eigenvalues");

  Random         random;
  Vector<double> g(n), Xg(n), MXg(n);
  unsigned int   n_positive = 0;
  double         residual   = 0;
  for (unsigned int t = 0; t < 1000; ++t)
    {
      for (unsigned int a = 0; a < n; ++a)
        g[a] = random() * std::sqrt(M(a, a));
      X.vmult(Xg, g);
      n_positive += (g * Xg > 0.);
      M.vmult(MXg, Xg);
      MXg -= g;
      residual = std::max(residual, MXg.l2_norm() / g.l2_norm());
    }
  std::cout << "positive g^T M^-1 g: " << n_positive << " of 1000" << std::endl;
  check(n_positive == 1000, "g^T M^-1 g > 0 for every random g");
  check(residual < 1e-4, "M M^-1 g = g to 1e-4 relative");
  return exit_code();
}
