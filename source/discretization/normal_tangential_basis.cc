#include <fosls_contact/discretization/normal_tangential_basis.h>

#include <cmath>

namespace FoslsContact
{
  template <int dim>
  FullMatrix<double>
  NormalTangentialBasis<dim>::householder(const Tensor<1, dim> &n)
  {
    // H = I - 2 w w^T with w = (n - e_1)/|n - e_1|: symmetric, orthogonal,
    // and H e_1 = n, so the first rotated coordinate is the normal one.
    FullMatrix<double> H(dim, dim);
    Tensor<1, dim>     w = n;
    w[0] -= 1.;
    const double norm = w.norm();
    for (unsigned int i = 0; i < dim; ++i)
      H(i, i) = 1.;
    if (norm < householder_tolerance)
      return H;
    w /= norm;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        H(i, j) -= 2. * w[i] * w[j];
    return H;
  }


  template <int dim>
  FullMatrix<double>
  NormalTangentialBasis<dim>::vertex_rotation(const Tensor<1, dim> &n)
  {
    if (dim == 1 || n[0] != 0.)
      return householder(n);
    // n _|_ e_1: columns n, sign(n_j) e_1 at j = argmax |n_j| and, in 3D,
    // the unit part of e_k orthogonal to n at the other k. For n = +-e_j
    // this is H(n); in general e_1, and every e_k with n_k = 0, is a column
    // (H(n) would mix u_1 into every rotated coordinate).
    unsigned int j = 1;
    for (unsigned int k = 2; k < dim; ++k)
      if (std::abs(n[k]) > std::abs(n[j]))
        j = k;
    FullMatrix<double> R(dim, dim);
    for (unsigned int i = 0; i < dim; ++i)
      R(i, 0) = n[i];
    R(0, j) = (n[j] > 0 ? 1. : -1.);
    for (unsigned int k = 1; k < dim; ++k)
      if (k != j)
        {
          Tensor<1, dim> t;
          t[k] = 1.;
          t -= n[k] * n;
          t /= t.norm();
          for (unsigned int i = 0; i < dim; ++i)
            R(i, k) = t[i];
        }
    return R;
  }

  template class NormalTangentialBasis<2>;
  template class NormalTangentialBasis<3>;
} // namespace FoslsContact
