// Checks the convergence orders of the FOSLS discretization Q1^2 x RT0^2
// (paper section 4.1) on the manufactured smooth solution of
// prm/elasticity_mms.prm (no contact: one direct solve per level), on
// levels 3..6: the H1 error of u and the H(div) error of sigma (the
// summary.json fields error_u_h1, error_sigma_hdiv) must decrease with
// order 1 (asserted in [0.9, 1.2] for the last two refinements); the L2
// error of u is reported and must be at least of order 1.8.
// ctest: timeout=120
#include <deal.II/base/mpi.h>

#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/output/postprocessor.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/monitor.h>

#include "tests.h"

using namespace FoslsContactTests;

int
main(int argc, char *argv[])
{
  // MPI first: the mesh is a parallel::distributed::Triangulation, and the
  // reference solver factorizes with Trilinos (Amesos KLU)
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  std::vector<ErrorNorms> errors;
  const unsigned int      first = 3, last = 6;
  for (unsigned int levels = first; levels <= last; ++levels)
    {
      const auto parameters =
        make_parameters(scene_file("elasticity_mms.prm"),
                        {{"Geometry/Levels", std::to_string(levels)},
                         {"Solver/Type", "active set"}});
      const Scene<2>          scene(parameters);
      const Discretization<2> discretization(scene, levels, MPI_COMM_WORLD);
      const unsigned int      L = discretization.finest_level();
      ConstrainedQP           qp;
      qp.reinit(discretization.level(L));
      FoslsAssembler<2>(discretization, parameters.weights)
        .assemble(L, qp);
      LevelVector              x = qp.new_vector();
      const ConditionalOStream quiet(std::cout, false);
      Monitor                  monitor(qp, parameters.solver, quiet, "active set");
      ActiveSetDirect().solve(qp, x, monitor);
      check(monitor.converged() && monitor.iterations() == 1 &&
              qp.kkt_residual(x).max() < 1e-10,
            "levels = " + std::to_string(levels) +
              ": no contact, one direct solve, KKT residual < 1e-10");

      const Postprocessor<2> post(discretization, parameters);
      errors.push_back(post.errors(post.solution_in_scene_units(x)));
      std::cout << "levels = " << levels << ": dofs = " << qp.size()
                << ", error_u_l2 = " << rounded(errors.back().u_l2)
                << ", error_u_h1 = " << rounded(errors.back().u_h1())
                << ", error_sigma_hdiv = " << rounded(errors.back().sigma_hdiv())
                << std::endl;
    }

  for (unsigned int k = 1; k < errors.size(); ++k)
    {
      const auto order = [](const double coarse, const double fine) {
        return std::log2(coarse / fine);
      };
      const double o_l2    = order(errors[k - 1].u_l2, errors[k].u_l2);
      const double o_h1    = order(errors[k - 1].u_h1(), errors[k].u_h1());
      const double o_sigma = order(errors[k - 1].sigma_hdiv(), errors[k].sigma_hdiv());
      const std::string step =
        std::to_string(first + k - 1) + " -> " + std::to_string(first + k);
      std::cout << std::fixed << std::setprecision(2) << "levels " << step
                << ": order u L2 = " << o_l2 << ", order u H1 = " << o_h1
                << ", order sigma H(div) = " << o_sigma << std::defaultfloat
                << std::endl;
      if (k + 2 >= errors.size())
        check(o_h1 >= 0.9 && o_h1 <= 1.2 && o_sigma >= 0.9 && o_sigma <= 1.2 &&
                o_l2 >= 1.8,
              "levels " + step + ": orders u H1, sigma H(div) in [0.9, 1.2], u L2 >= 1.8");
    }
  return exit_code();
}
