#include <deal.II/lac/lapack_full_matrix.h>

#include <fosls_contact/solvers/spd_inverse.h>

namespace FoslsContact
{
  void
  invert_spd(FullMatrix<double> &M)
  {
    const unsigned int n = M.m();
    if (n == 0)
      return;
    LAPACKFullMatrix<double> inverse(n, n);
    inverse = M;
    // (the symmetric property makes invert() use potrf and potri, and fill
    // both triangles of the result)
    inverse.set_property(LAPACKSupport::symmetric);
    try
      {
        inverse.invert();
      }
    catch (const ExceptionBase &)
      {
        // not positive definite in floating point: weights many orders of
        // magnitude apart (C_eq = 1e30). Gauss-Jordan pivots and returns
        // some inverse; the iterates it gives are caught as not finite or
        // as a growing J by the monitor, which names the weights.
        M.gauss_jordan();
        return;
      }
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = 0; b < n; ++b)
        M(a, b) = inverse(a, b);
  }
} // namespace FoslsContact
