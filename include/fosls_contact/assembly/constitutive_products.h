#ifndef fosls_contact_assembly_constitutive_products_h
#define fosls_contact_assembly_constitutive_products_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Which compiled version of the loop add_constitutive_products() runs:
   * the processor's (AVX2 where processor_has_avx2(), else SSE2), or one
   * by name, for tests/unit/constitutive_products, which runs both (avx2
   * only where processor_has_avx2()).
   */
  enum class ProductsVersion
  {
    processor,
    sse2,
    avx2
  };

  /**
   * The constitutive term of one quadrature point of a cell,
   * K(i, j) += c (r_i : r_j) JxW for the DoFs j <= i < @p n, where r_i =
   * @p residual[i] = A sigma_i - eps(u_i). It is most of the assembly's
   * time: n^2 / 2 products of dim x dim tensors at every quadrature point
   * (n = 42 and 27 points in 3D).
   *
   * The pairs go four j at a time (GCC's vector types). The program is
   * built for x86-64 in general, whose SSE2 takes two doubles an
   * instruction; the loop is compiled a second time for AVX2 (four), which
   * runs where the processor has it. Each lane does what
   * scalar_product(r_i, r_j) does, in its order (a row's products summed
   * from the first column, then the rows' sums from the first row), then
   * multiplies by c and then by JxW, as `K(i, j) += c *
   * scalar_product(r_i, r_j) * JxW` does: every entry has the same bits as
   * that loop, in either version, since neither target fuses a product
   * into its sum (no FMA). tests/unit/constitutive_products checks both
   * versions against that loop bit for bit.
   *
   * @p components is scratch space, resized here. @p version: which of
   * the compiled versions runs.
   */
  template <int dim>
  void
  add_constitutive_products(const Tensor<2, dim> *residual,
                            unsigned int          n,
                            double                c,
                            double                JxW,
                            std::vector<double> & components,
                            FullMatrix<double> &  K,
                            ProductsVersion       version = ProductsVersion::processor);

  /** Whether this processor has AVX2. */
  bool
  processor_has_avx2();
} // namespace FoslsContact

#endif
