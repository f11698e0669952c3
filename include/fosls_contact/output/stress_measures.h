#ifndef fosls_contact_output_stress_measures_h
#define fosls_contact_output_stress_measures_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The scalar stress measures engineers read, from the FOSLS stress
   * sigma_h. sigma_h is symmetric only up to the constitutive residual
   * (paper section 2: |sigma - sigma^T| <= C |A sigma - eps(u)|), so the
   * measures take its symmetric part. In 2D the body is in plane strain,
   * where the out-of-plane stress is sigma_zz = nu (sigma_xx + sigma_yy)
   * (nu = 1/2 for lambda = inf); it enters the von Mises stress and the
   * pressure as in a 3D body.
   */
  namespace StressMeasures
  {
    /** The 3D stress tensor of @p sigma (its symmetric part). */
    template <int dim>
    SymmetricTensor<2, 3>
    full_stress(const Tensor<2, dim> &sigma, const double poisson_ratio)
    {
      SymmetricTensor<2, 3> s;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          s[i][j] = 0.5 * (sigma[i][j] + sigma[j][i]);
      if (dim == 2)
        s[2][2] = poisson_ratio * (s[0][0] + s[1][1]);
      return s;
    }

    /** sqrt(3/2 dev(s) : dev(s)). */
    template <int dim>
    double
    von_mises(const Tensor<2, dim> &sigma, const double poisson_ratio)
    {
      const SymmetricTensor<2, 3> d = deviator(full_stress(sigma, poisson_ratio));
      return std::sqrt(1.5 * (d * d));
    }

    /** The hydrostatic pressure -tr(s)/3 (positive in compression). */
    template <int dim>
    double
    pressure(const Tensor<2, dim> &sigma, const double poisson_ratio)
    {
      return -trace(full_stress(sigma, poisson_ratio)) / 3.;
    }
  } // namespace StressMeasures
} // namespace FoslsContact

#endif
