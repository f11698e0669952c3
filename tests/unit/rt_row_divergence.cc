// Pins a deal.II 9.4.1 pitfall that the assembly works around (see
// source/assembly/fosls_assembler.cc): for the program's element
// FESystem(FE_Q(1)^d, FE_RaviartThomas(0)^d), with stress row m stored in
// components dim + m*dim ... dim + m*dim + dim-1,
//  - FEValuesExtractors::Vector(dim + m*dim) gives the right divergence of
//    row m (asserted, for an interpolated linear RT0 field and shape by
//    shape);
//  - FEValuesExtractors::Tensor<2>(dim).divergence() does not (reported:
//    on deal.II 9.4.1 it is zero for these non-primitive RT components).
// If a deal.II upgrade fixes the Tensor extractor, the reported line
// changes and this test fails: the workaround can then be revisited.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_raviart_thomas.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include "tests.h"

using namespace FoslsContactTests;

/**
 * u = 0, row m of sigma: component k = a_mk + b_mk x_k, which lies in RT0
 * on axis-parallel boxes; div(row m) = sum_k b_mk.
 */
template <int dim>
class LinearStress : public Function<dim>
{
public:
  LinearStress()
    : Function<dim>(dim + dim * dim)
  {}

  static double a(const unsigned int m, const unsigned int k) { return 0.5 + m - 0.25 * k; }
  static double b(const unsigned int m, const unsigned int k) { return 1. + 2. * m + 0.5 * k; }
  static double
  divergence(const unsigned int m)
  {
    double d = 0;
    for (unsigned int k = 0; k < dim; ++k)
      d += b(m, k);
    return d;
  }

  double
  value(const Point<dim> &p, const unsigned int component) const override
  {
    if (component < dim)
      return 0;
    const unsigned int m = (component - dim) / dim, k = (component - dim) % dim;
    return a(m, k) + b(m, k) * p[k];
  }
};


template <int dim>
void
test()
{
  std::cout << "--- dim = " << dim << std::endl;
  Triangulation<dim>        tria;
  std::vector<unsigned int> repetitions(dim, 1);
  repetitions[0] = 2;
  Point<dim> p1, p2;
  for (unsigned int d = 0; d < dim; ++d)
    p2[d] = 1. + 0.5 * d;
  p2[0] = 2.;
  GridGenerator::subdivided_hyper_rectangle(tria, repetitions, p1, p2);
  tria.refine_global(1);

  const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_RaviartThomas<dim>(0), dim);
  DoFHandler<dim>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<dim> mapping(1);

  Vector<double>          x(dof_handler.n_dofs());
  const LinearStress<dim> function;
  VectorTools::interpolate(mapping, dof_handler, function, x);

  const QGauss<dim> quadrature(2);
  FEValues<dim>     fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients |
                            update_quadrature_points);
  const unsigned int nq = quadrature.size();

  const FEValuesExtractors::Tensor<2> tensor(dim);
  std::vector<Tensor<1, dim>>         tensor_div(nq);
  std::vector<double>                 row_div(nq);
  std::vector<Tensor<1, dim>>         row_value(nq);

  double value_error = 0, row_error = 0, tensor_error = 0, tensor_size = 0;
  double shape_row_vs_gradient = 0, shape_tensor = 0, shape_row = 0;
  for (const auto &cell : dof_handler.active_cell_iterators())
    {
      fe_values.reinit(cell);
      fe_values[tensor].get_function_divergences(x, tensor_div);
      for (unsigned int m = 0; m < dim; ++m)
        {
          const FEValuesExtractors::Vector row(dim + m * dim);
          fe_values[row].get_function_values(x, row_value);
          fe_values[row].get_function_divergences(x, row_div);
          for (unsigned int q = 0; q < nq; ++q)
            {
              for (unsigned int k = 0; k < dim; ++k)
                value_error =
                  std::max(value_error,
                           std::abs(row_value[q][k] -
                                    function.value(fe_values.quadrature_point(q),
                                                   dim + m * dim + k)));
              row_error = std::max(row_error,
                                   std::abs(row_div[q] - LinearStress<dim>::divergence(m)));
              tensor_error =
                std::max(tensor_error,
                         std::abs(tensor_div[q][m] - LinearStress<dim>::divergence(m)));
              tensor_size = std::max(tensor_size, std::abs(tensor_div[q][m]));
            }
        }

      // shape by shape: the row divergence is the trace of the row's
      // gradient (components dim + m*dim + k), the Tensor one is not
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        for (unsigned int q = 0; q < nq; ++q)
          for (unsigned int m = 0; m < dim; ++m)
            {
              const FEValuesExtractors::Vector row(dim + m * dim);
              const Tensor<2, dim> grad = fe_values[row].gradient(i, q);
              shape_row_vs_gradient =
                std::max(shape_row_vs_gradient,
                         std::abs(fe_values[row].divergence(i, q) - trace(grad)));
              shape_row = std::max(shape_row, std::abs(fe_values[row].divergence(i, q)));
              shape_tensor =
                std::max(shape_tensor, std::abs(fe_values[tensor].divergence(i, q)[m]));
            }
    }

  check(value_error < 1e-12, "interpolated field reproduces the linear RT0 stress");
  check(row_error < 1e-12,
        "Vector(dim + m*dim) extractor: div(row m) exact for every row");
  check(shape_row_vs_gradient < 1e-12 && shape_row > 1.,
        "Vector(dim + m*dim) extractor: shape divergence = trace of shape gradient");
  std::cout << "exact divergences of the rows:";
  for (unsigned int m = 0; m < dim; ++m)
    std::cout << ' ' << LinearStress<dim>::divergence(m);
  std::cout << std::endl;
  // Report what the Tensor<2> extractor gives (not an assertion of
  // correctness: the point is that it is wrong on deal.II 9.4.1).
  std::cout << "Tensor<2>(dim) extractor: "
            << (tensor_error < 1e-12 ?
                  "divergence correct" :
                  tensor_size < 1e-12 ?
                  "divergence ZERO for the RT components (deal.II 9.4 pitfall)" :
                  "divergence WRONG (nonzero)")
            << "; largest shape-function divergence "
            << (shape_tensor < 1e-12 ? "0" : "nonzero") << std::endl;
}


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  test<2>();
  test<3>();
  return exit_code();
}
