#ifndef fosls_contact_solvers_spd_inverse_h
#define fosls_contact_solvers_spd_inverse_h

#include <deal.II/lac/full_matrix.h>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Replace the symmetric positive definite @p M by its inverse, computed
   * from its Cholesky factor, M = U^T U, as M^{-1} = U^{-1} U^{-T} (LAPACK
   * potrf and potri). Where LAPACK finds M not positive definite in
   * floating point, by Gauss-Jordan elimination with pivoting instead.
   *
   * Why not Gauss-Jordan: the patch matrices of the smoother are badly
   * conditioned where cells differ much in size. An RT0 basis function has
   * unit flux through its face, so its divergence term grows like
   * C_eq h^{-d}, while the strain term of a Q1 displacement function
   * shrinks like h^{d-2}. On the quarter ball of prm/quarter_ball_file.prm
   * (3D, cells differing in size by a factor 15) refined to four levels,
   * a patch matrix's diagonal spans 4e-3 to 4e10 and its condition number
   * scaled to a unit diagonal is 1.3e9 (tests/unit/spd_inverse). An
   * inverse formed by elimination has errors of about eps times the
   * condition number times |M^{-1}|, larger there than the smallest
   * eigenvalue of M^{-1}: it was indefinite, g^T M^{-1} g < 0 for some
   * patch defects g, and the patch steps raised J until the cycle
   * diverged. The product of the triangular inverses is a
   * Gram matrix whose rounding errors are relative to |M^{-1}| itself, so
   * it stays positive definite while eps times the condition number is
   * below 1, and every patch step lowers J (tests/solver/ill_conditioned_patches).
   */
  void invert_spd(FullMatrix<double> &M);
} // namespace FoslsContact

#endif
