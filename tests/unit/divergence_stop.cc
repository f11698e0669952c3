// Checks the divergence stop of Monitor (Solver: a descent method's J may
// not grow): on the square of prm/square.prm, 2 levels, from the active
// set solver's minimizer x*, a step along a free DoF raises J by
// 0.5 t^2 a_ii (the gradient is zero there):
//  - by 1e-3 J*: a monitor with enable_divergence_detection() stops,
//    not converged, stop_reason "diverged";
//  - by 1e-8 J* (below Monitor::divergence_tolerance, the evaluation
//    error of J it allows): no divergence;
//  - by 1e-3 J* without enable_divergence_detection() (the active set
//    method, no descent method): no divergence.
#include <deal.II/base/mpi.h>

#include <fosls_contact/assembly/fosls_assembler.h>
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
  const auto parameters = make_parameters(scene_file("square.prm"),
                                          {{"Geometry/Levels", "2"},
                                           {"Solver/Type", "active set"},
                                           {"Solver/Max iterations", "50"}});
  const Scene<2>          scene(parameters);
  const Discretization<2> discretization(scene, 2, MPI_COMM_WORLD);
  ConstrainedQP           qp;
  const unsigned int      L = discretization.finest_level();
  qp.reinit(discretization.level(L));
  FoslsAssembler<2>(discretization, parameters.weights).assemble(L, qp);

  const ConditionalOStream quiet(std::cout, false);
  LevelVector              x = qp.new_vector();
  {
    Monitor monitor(qp, parameters.solver, quiet, "active set");
    ActiveSetDirect().solve(qp, x, monitor);
    check(monitor.converged(), "the active set solver converged");
  }
  const double J = qp.value(x);

  // the free DoF with the largest diagonal entry
  unsigned int i = numbers::invalid_unsigned_int;
  for (unsigned int k = 0; k < qp.n_owned(); ++k)
    if (qp.role[k] == DoFRole::free &&
        (i == numbers::invalid_unsigned_int ||
         qp.matrix.diag_element(k) > qp.matrix.diag_element(i)))
      i = k;

  auto run = [&](const double increase, const bool detect) {
    Monitor monitor(qp, parameters.solver, quiet, "test");
    if (detect)
      monitor.enable_divergence_detection();
    monitor.start(x);
    LevelVector y = x;
    y.local_element(i) += std::sqrt(2. * increase * J / qp.matrix.diag_element(i));
    y.update_ghost_values();
    const bool stop = monitor.report(y, x);
    std::cout << "J raised by " << increase << " J*, detection "
              << (detect ? "on" : "off") << ": J(new)/J* - 1 = "
              << rounded(qp.value(y) / J - 1., 2) << ", stop " << stop
              << ", converged " << monitor.converged() << ", stop_reason \""
              << monitor.stop_reason() << "\"" << std::endl;
    return std::make_pair(stop, monitor.stop_reason());
  };
  const auto large = run(1e-3, true);
  check(large.first && large.second == "diverged",
        "an increase of 1e-3 J* stops the run as diverged");
  const auto small = run(1e-8, true);
  check(small.second != "diverged", "an increase of 1e-8 J* is within the tolerance");
  const auto off = run(1e-3, false);
  check(off.second != "diverged", "no divergence stop without enable_divergence_detection()");
  return exit_code();
}
