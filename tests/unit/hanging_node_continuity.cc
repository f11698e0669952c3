// The hanging-node constraints of the program's element
// FESystem(FE_Q(1)^d, FE_RaviartThomas(0)^d) on locally refined meshes, as
// deal.II 9.4.1 builds them (DoFTools::make_hanging_node_constraints): a
// conforming function of the mixed space needs a continuous displacement u
// and a continuous normal flux sigma n (each stress row's normal component)
// across every face between a coarse cell and its refined neighbours.
//
// For a random vector made conforming by the constraints
// (AffineConstraints::distribute), the largest jump of u and of sigma n over
// the quadrature points of all refined faces must be round-off; for the
// same vector without the constraints it must not be (so the check can
// fail). Meshes: the unit square/cube with one cell refined twice and its
// neighbour once, and the ball (in 2D its cells' faces have mixed
// orientations, so the RT0 face signs differ between neighbours).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_raviart_thomas.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <random>
#include <string>

#include "tests.h"

using namespace FoslsContactTests;

struct Jumps
{
  double       u = 0, flux = 0, scale = 0;
  unsigned int faces = 0;
};

/**
 * The largest jumps of u and sigma n of @p x over the faces where a cell
 * meets a coarser neighbour, at the Gauss points of the fine face (found on
 * the coarse side by position).
 */
template <int dim>
Jumps
face_jumps(const DoFHandler<dim> &dof_handler, const Vector<double> &x)
{
  const auto &          fe = dof_handler.get_fe();
  const QGauss<dim - 1> quadrature(2);
  const UpdateFlags     flags =
    update_values | update_quadrature_points | update_normal_vectors;
  const MappingQ1<dim>  mapping; // (FEValues keep a reference to it)
  FEFaceValues<dim>    fine(mapping, fe, quadrature, flags);
  FESubfaceValues<dim> coarse(mapping, fe, quadrature, flags);
  const unsigned int   nq = quadrature.size();

  std::vector<Tensor<1, dim>>              u_fine(nq), u_coarse(nq);
  std::vector<std::vector<Tensor<1, dim>>> rows_fine(dim, std::vector<Tensor<1, dim>>(nq)),
    rows_coarse(dim, std::vector<Tensor<1, dim>>(nq));
  const FEValuesExtractors::Vector displacement(0);

  Jumps jumps;
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (!cell->at_boundary(f) && cell->neighbor_is_coarser(f))
        {
          const auto neighbor = cell->neighbor(f);
          const auto face     = cell->neighbor_of_coarser_neighbor(f);
          fine.reinit(cell, f);
          coarse.reinit(neighbor, face.first, face.second);
          fine[displacement].get_function_values(x, u_fine);
          coarse[displacement].get_function_values(x, u_coarse);
          for (unsigned int m = 0; m < dim; ++m)
            {
              // one extractor per stress row (the Tensor<2> extractor is
              // not reliable for these RT components, tests/unit/rt_row_divergence)
              const FEValuesExtractors::Vector row(dim + m * dim);
              fine[row].get_function_values(x, rows_fine[m]);
              coarse[row].get_function_values(x, rows_coarse[m]);
            }
          for (unsigned int q = 0; q < nq; ++q)
            {
              // the coarse side's Gauss point at the same position
              unsigned int p = 0;
              for (unsigned int r = 1; r < nq; ++r)
                if (coarse.quadrature_point(r).distance(fine.quadrature_point(q)) <
                    coarse.quadrature_point(p).distance(fine.quadrature_point(q)))
                  p = r;
              AssertThrow(coarse.quadrature_point(p).distance(fine.quadrature_point(q)) < 1e-12,
                          ExcMessage("the two sides' Gauss points differ"));
              const Tensor<1, dim> n = fine.normal_vector(q);
              jumps.u = std::max(jumps.u, (u_fine[q] - u_coarse[p]).norm());
              for (unsigned int m = 0; m < dim; ++m)
                {
                  jumps.flux =
                    std::max(jumps.flux, std::abs((rows_fine[m][q] - rows_coarse[m][p]) * n));
                  jumps.scale = std::max(jumps.scale, std::abs(rows_fine[m][q] * n));
                }
              jumps.scale = std::max(jumps.scale, u_fine[q].norm());
            }
          ++jumps.faces;
        }
  return jumps;
}


template <int dim>
void
check_mesh(const std::string &name, Triangulation<dim> &triangulation)
{
  const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_RaviartThomas<dim>(0), dim);
  DoFHandler<dim>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);

  AffineConstraints<double> constraints;
  DoFTools::make_hanging_node_constraints(dof_handler, constraints);
  constraints.close();

  // the constrained DoFs of each kind: displacement (Q1 vertices) and flux
  // (RT0 faces)
  unsigned int n_u = 0, n_flux = 0;
  {
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<bool>                    seen(dof_handler.n_dofs());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (!seen[dofs[i]] && constraints.is_constrained(dofs[i]))
            {
              seen[dofs[i]] = true;
              ++(fe.system_to_base_index(i).first.first == 0 ? n_u : n_flux);
            }
      }
  }

  std::mt19937                           generator(42);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  Vector<double>                         x(dof_handler.n_dofs());
  for (auto &xi : x)
    xi = uniform(generator);
  const Jumps free = face_jumps(dof_handler, x);
  constraints.distribute(x);
  const Jumps conforming = face_jumps(dof_handler, x);

  std::cout << dim << "D " << name << ": " << triangulation.n_active_cells() << " cells, "
            << dof_handler.n_dofs() << " DoFs, " << conforming.faces
            << " fine faces at a coarser neighbour, constrained: " << n_u << " displacement, "
            << n_flux << " flux DoFs" << std::endl;
  check(n_u > 0 && n_flux > 0, "  both kinds of DoFs are constrained");
  check(conforming.u <= 1e-12 * conforming.scale,
        "  constrained: u continuous (largest jump / largest value <= 1e-12)");
  check(conforming.flux <= 1e-12 * conforming.scale,
        "  constrained: sigma n continuous (largest jump / largest value <= 1e-12)");
  check(free.u > 1e-2 * free.scale && free.flux > 1e-2 * free.scale,
        "  unconstrained: u and sigma n jump (> 1e-2 of the largest value)");
}


template <int dim>
void
run()
{
  {
    Triangulation<dim> triangulation;
    GridGenerator::hyper_cube(triangulation);
    triangulation.refine_global(1);
    triangulation.begin_active()->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();
    // one of the refined cell's children once more (2:1 with its neighbours)
    triangulation.begin_active(2)->set_refine_flag();
    triangulation.prepare_coarsening_and_refinement();
    triangulation.execute_coarsening_and_refinement();
    check_mesh("unit box, local refinement", triangulation);
  }
  {
    Triangulation<dim> triangulation;
    GridGenerator::hyper_ball(triangulation);
    // flat faces: with the ball's manifolds the children's vertices move off
    // the coarse neighbour's (Q1) faces, and the two sides do not meet
    triangulation.reset_all_manifolds();
    triangulation.refine_global(1);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->center()[0] > 0)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();
    check_mesh("ball, the half x > 0 refined", triangulation);
  }
}


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run<2>();
  run<3>();
  return exit_code();
}
