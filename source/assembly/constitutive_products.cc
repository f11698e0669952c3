#include <fosls_contact/assembly/constitutive_products.h>

#include <cstring>

// On x86-64 the loop is compiled for SSE2 and for AVX2; elsewhere twice the
// same.
#if defined(__x86_64__)
#  define FOSLS_CONTACT_TARGET_AVX2 __attribute__((target("avx2")))
#else
#  define FOSLS_CONTACT_TARGET_AVX2
#endif

namespace FoslsContact
{
  namespace
  {
    constexpr unsigned int width = 4;
    typedef double Pack __attribute__((vector_size(width * sizeof(double))));

    inline __attribute__((always_inline)) Pack
    load(const double *p)
    {
      Pack v;
      std::memcpy(&v, p, sizeof(v));
      return v;
    }

    /**
     * The loop of add_constitutive_products(), inlined into each version
     * (each compiles it for its own target). The padding of components
     * stays zero: nothing writes it after the assign().
     */
    template <int dim>
    inline __attribute__((always_inline)) void
    constitutive_products(const Tensor<2, dim> *residual,
                          const unsigned int    n,
                          const double          c,
                          const double          JxW,
                          std::vector<double> & components,
                          FullMatrix<double> &  K)
    {
      // the residuals by component: component (a, b) of DoF j at
      // (a dim + b) stride + j, zero in the padding up to whole packs
      const unsigned int stride = (n + width - 1) / width * width;
      if (components.size() != dim * dim * stride)
        components.assign(dim * dim * stride, 0.);
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            components[(a * dim + b) * stride + j] = residual[j][a][b];
      for (unsigned int i = 0; i < n; ++i)
        {
          const Tensor<2, dim> &r_i = residual[i];
          for (unsigned int j = 0; j <= i; j += width)
            {
              Pack sum;
              for (unsigned int a = 0; a < dim; ++a)
                {
                  Pack row = load(&components[(a * dim) * stride + j]) * r_i[a][0];
                  for (unsigned int b = 1; b < dim; ++b)
                    row += load(&components[(a * dim + b) * stride + j]) * r_i[a][b];
                  sum = a == 0 ? row : sum + row;
                }
              const Pack term = c * sum * JxW;
              for (unsigned int k = 0; k < width && j + k <= i; ++k)
                K(i, j + k) += term[k];
            }
        }
    }

    /** The loop for any x86-64 processor (SSE2). */
    template <int dim>
    void
    products_sse2(const Tensor<2, dim> *residual,
                  const unsigned int    n,
                  const double          c,
                  const double          JxW,
                  std::vector<double> & components,
                  FullMatrix<double> &  K)
    {
      constitutive_products<dim>(residual, n, c, JxW, components, K);
    }


    /** The loop for AVX2. */
    template <int dim>
    FOSLS_CONTACT_TARGET_AVX2 void
    products_avx2(const Tensor<2, dim> *residual,
                  const unsigned int    n,
                  const double          c,
                  const double          JxW,
                  std::vector<double> & components,
                  FullMatrix<double> &  K)
    {
      constitutive_products<dim>(residual, n, c, JxW, components, K);
    }
  } // namespace


  bool
  processor_has_avx2()
  {
#if defined(__x86_64__)
    static const bool avx2 = __builtin_cpu_supports("avx2");
    return avx2;
#else
    return false;
#endif
  }


  template <int dim>
  void
  add_constitutive_products(const Tensor<2, dim> *residual,
                            const unsigned int    n,
                            const double          c,
                            const double          JxW,
                            std::vector<double> & components,
                            FullMatrix<double> &  K,
                            const ProductsVersion version)
  {
    switch (version)
      {
        case ProductsVersion::sse2:
          products_sse2<dim>(residual, n, c, JxW, components, K);
          break;
        case ProductsVersion::avx2:
          products_avx2<dim>(residual, n, c, JxW, components, K);
          break;
        default:
          if (processor_has_avx2())
            products_avx2<dim>(residual, n, c, JxW, components, K);
          else
            products_sse2<dim>(residual, n, c, JxW, components, K);
      }
  }


  template void
  add_constitutive_products<2>(const Tensor<2, 2> *,
                               unsigned int,
                               double,
                               double,
                               std::vector<double> &,
                               FullMatrix<double> &,
                               ProductsVersion);
  template void
  add_constitutive_products<3>(const Tensor<2, 3> *,
                               unsigned int,
                               double,
                               double,
                               std::vector<double> &,
                               FullMatrix<double> &,
                               ProductsVersion);
} // namespace FoslsContact
