// Checks add_constitutive_products(), the constitutive term
// K(i, j) += c (r_i : r_j) JxW of the assembly four pairs at a time, against
// the loop it replaces, K(i, j) += c * scalar_product(r_i, r_j) * JxW one
// pair after the other: the same bits for every entry, in 2D and 3D, for
// numbers of DoFs that fill whole packs of four and that do not, summed
// over several quadrature points, with residuals of mixed magnitudes and
// signs, exact zeros among them (a shape function's residual has a zero
// half). Both versions are checked: the one for any x86-64 processor and,
// where the processor has AVX2, the AVX2 one; the assembly runs the latter
// where it can.
#include <fosls_contact/assembly/constitutive_products.h>

#include "tests.h"

#include <cstring>

using namespace FoslsContactTests;

template <int dim>
std::vector<Tensor<2, dim>>
random_residuals(Random &random, const unsigned int n)
{
  std::vector<Tensor<2, dim>> r(n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        {
          // a zero half for every other function, and magnitudes from 1e-8
          // to 1e8
          if ((i % 2 == 0) == (a == b))
            r[i][a][b] = (random() < 0 ? -0. : 0.);
          else
            r[i][a][b] = random() * std::pow(10., std::round(8 * random()));
        }
  return r;
}


template <int dim>
void
test(const unsigned int n)
{
  Random             random(n + dim);
  const double       c = 1. + random();
  FullMatrix<double> loop(n, n), sse2(n, n), avx2(n, n), dispatched(n, n);
  std::vector<double> scratch;
  for (unsigned int q = 0; q < 5; ++q)
    {
      const auto   r   = random_residuals<dim>(random, n);
      const double JxW = 0.5 + random();
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j <= i; ++j)
          loop(i, j) += c * scalar_product(r[i], r[j]) * JxW;
      add_constitutive_products<dim>(r.data(), n, c, JxW, scratch, sse2, ProductsVersion::sse2);
      if (processor_has_avx2())
        add_constitutive_products<dim>(r.data(), n, c, JxW, scratch, avx2, ProductsVersion::avx2);
      add_constitutive_products<dim>(r.data(), n, c, JxW, scratch, dispatched);
    }
  const auto same_bits = [&](const FullMatrix<double> &k) {
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (std::memcmp(&k(i, j), &loop(i, j), sizeof(double)) != 0)
          return false;
    return true;
  };
  const std::string what = "dim = " + std::to_string(dim) + ", n = " + std::to_string(n);
  check(same_bits(sse2), what + ", any x86-64: the loop's bits");
  check(!processor_has_avx2() || same_bits(avx2), what + ", AVX2 where present: the loop's bits");
  check(same_bits(dispatched), what + ", the version the assembly runs: the loop's bits");
  // (the upper triangle is the assembler's to fill)
  bool upper_untouched = true;
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = i + 1; j < n; ++j)
      upper_untouched &= dispatched(i, j) == 0.;
  check(upper_untouched, what + ", j > i untouched");
}


int
main()
{
  for (const unsigned int n : {1u, 7u, 16u})
    test<2>(n);
  for (const unsigned int n : {13u, 42u})
    test<3>(n);
  return exit_code();
}
