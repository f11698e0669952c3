// Checks the solvers on the square of prm/square.prm (paper section 7):
//  - ActiveSetDirect on 2 and 4 levels converges to the discrete KKT
//    point: converged, KKT residual < 1e-10, feasible, multipliers
//    mu = b - A x >= 0 on bounded DoFs and mu = 0 where the bound is not
//    attained (complementarity), and all contact vertices in contact (the
//    block is pushed down onto the flat foundation);
//  - ProjectedGaussSeidel converges toward the same solution: the energy
//    distance to it and J - J* decrease over 3 batches of sweeps (2 and 3
//    levels), on 2 levels down to < 1e-2 (J - J* < 1e-4 J*) with the same
//    contact set after 36000 sweeps (the diagonally scaled FOSLS matrix has
//    condition ~3e4 there: PGS contracts by ~0.9997 per sweep); J never
//    increases (Monitor::energy_increases() == 0 and a monotone history;
//    the runs stop well before J's changes reach its round-off).
//  - the assembled matrix is on the pattern of its entries above
//    round-off, and symmetric.
// Functional values are printed scaled by 1e7 (they are ~1e-7).
// Runs on one MPI process, which owns every DoF (the LevelVectors' local
// indices = global ones).
// ctest: timeout=120
#include <deal.II/base/mpi.h>

#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/monitor.h>
#include <fosls_contact/solvers/projected_gauss_seidel.h>

#include "tests.h"

#include <limits>

using namespace FoslsContactTests;

struct Problem
{
  Problem(const unsigned int levels,
          const std::string &solver,
          const unsigned int max_iterations = 200)
    : parameters(make_parameters(scene_file("square.prm"),
                                 {{"Geometry/Levels", std::to_string(levels)},
                                  {"Solver/Type", solver},
                                  {"Solver/Tolerance", "1e-9"},
                                  {"Solver/Max iterations",
                                   std::to_string(max_iterations)}}))
    , scene(parameters)
    , discretization(scene, levels, MPI_COMM_WORLD)
  {
    const unsigned int L = discretization.finest_level();
    qp.reinit(discretization.level(L));
    FoslsAssembler<2>(discretization, parameters.weights)
      .assemble(L, qp);
  }

  const Parameters::AllParameters parameters;
  const Scene<2>                  scene;
  const Discretization<2>         discretization;
  ConstrainedQP                   qp;
};


// The assembled A is on the pattern of its entries above round-off
// (ConstrainedQP::compress_matrices): no entry with |a_ij| <= 1e-13
// sqrt(a_ii a_jj) is left, fewer entries than the DoF coupling pattern,
// and the pattern is symmetric (the values are symmetric to round-off:
// the assembly sums a_ij and a_ji in different orders).
void
check_compressed_matrix(const unsigned int levels)
{
  std::cout << "--- compressed matrix, " << levels << " levels" << std::endl;
  Problem                  p(levels, "active set");
  const SparseMatrix<double> &A = p.qp.matrix;
  unsigned int              n_small = 0, n_asymmetric = 0;
  double                    asymmetry = 0;
  for (unsigned int i = 0; i < A.m(); ++i)
    for (auto e = A.begin(i); e != A.end(i); ++e)
      {
        const unsigned int j = e->column();
        n_small += std::abs(e->value()) <=
                   ConstrainedQP::round_off_drop *
                     std::sqrt(std::abs(A.diag_element(i) * A.diag_element(j)));
        n_asymmetric += !A.get_sparsity_pattern().exists(j, i);
        asymmetry = std::max(asymmetry,
                             std::abs(e->value() - A.el(j, i)) /
                               std::sqrt(std::abs(A.diag_element(i) * A.diag_element(j))));
      }
  const auto n_coupling =
    p.discretization.level(p.discretization.finest_level()).sparsity.n_nonzero_elements();
  check(n_small == 0, "no entry at round-off level");
  check(n_asymmetric == 0, "symmetric pattern");
  check(asymmetry < 1e-14, "symmetric values to round-off");
  check(A.n_nonzero_elements() < n_coupling, "fewer entries than the DoF coupling pattern");
}


LevelVector
solve_active_set(const unsigned int levels)
{
  std::cout << "--- active set, " << levels << " levels" << std::endl;
  Problem                  p(levels, "active set");
  const ConstrainedQP &    qp = p.qp;
  LevelVector              x  = qp.new_vector();
  const ConditionalOStream quiet(std::cout, false);
  Monitor                  monitor(qp, p.parameters.solver, quiet, "active set");
  ActiveSetDirect().solve(qp, x, monitor);

  const KKTResidual kkt = qp.kkt_residual(x);
  std::cout << "iterations = " << monitor.iterations()
            << ", active = " << qp.n_active(x)
            << ", 1e7 * J = " << rounded(1e7 * qp.value(x)) << std::endl;
  check(monitor.converged(), "converged");
  check(kkt.max() < 1e-10, "KKT residual < 1e-10");
  check(qp.max_violation(x) == 0., "feasible");

  // mu = b - A x, relative to the size of the terms of the rows (b = 0
  // here: the data enter through fixed values)
  LevelVector mu = qp.new_vector();
  vmult(qp.matrix, mu, x);
  mu.sadd(-1., 1., qp.rhs);
  double scale = qp.rhs.linfty_norm();
  for (unsigned int i = 0; i < qp.n_owned(); ++i)
    if (qp.role[i] != DoFRole::fixed)
      {
        double row = 0;
        for (auto e = qp.matrix.begin(i); e != qp.matrix.end(i); ++e)
          row += std::abs(e->value() * x.local_element(e->column()));
        scale = std::max(scale, row);
      }
  bool         sign_ok = true, complementarity_ok = true, free_ok = true;
  unsigned int n_vertices_in_contact = 0, n_positive = 0;
  for (unsigned int i = 0; i < qp.n_owned(); ++i)
    if (qp.role[i] == DoFRole::bounded)
      {
        const bool at_bound = x.local_element(i) == qp.upper_bounds.local_element(i);
        sign_ok &= mu.local_element(i) >= -1e-12 * scale;
        n_positive += (mu.local_element(i) > 1e-8 * scale);
        if (!at_bound)
          complementarity_ok &= std::abs(mu.local_element(i)) <= 1e-12 * scale;
      }
    else if (qp.role[i] == DoFRole::free)
      free_ok &= std::abs(mu.local_element(i)) <= 1e-12 * scale;
  std::cout << "bounded DoFs with a positive multiplier: " << n_positive << std::endl;
  for (const auto &cv :
       p.discretization.level(p.discretization.finest_level()).contact_vertices)
    n_vertices_in_contact += (x.local_element(cv.normal_dof) == cv.gap);
  check(sign_ok, "multipliers b - A x >= 0 on bounded DoFs");
  check(complementarity_ok, "multipliers vanish where the bound is not attained");
  check(free_ok, "A x = b on free DoFs");
  check(n_vertices_in_contact ==
          p.discretization.level(p.discretization.finest_level()).contact_vertices.size(),
        "every contact vertex is in contact");
  return x;
}


/**
 * PGS from x = 0 in @p n_batches batches of @p batch sweeps (each a fresh
 * solve() with a tolerance that is never met, continuing from the last
 * iterate): J never increases, and the energy distance to the active set
 * solution x* and J - J(x*) >= 0 decrease from batch to batch. At the end,
 * the contact set must be that of x*, and (if the bounds are finite) the
 * distance below @p distance_bound and the relative excess of J below
 * @p excess_bound.
 */
void
solve_gauss_seidel(const unsigned int levels,
                   const LevelVector &active_set_solution,
                   const unsigned int batch,
                   const unsigned int n_batches,
                   const double       distance_bound,
                   const double       excess_bound)
{
  std::cout << "--- projected Gauss-Seidel, " << levels << " levels, "
            << n_batches << " x " << batch << " sweeps" << std::endl;
  Problem p(levels, "projected gauss seidel", batch);
  auto    solver_parameters = p.parameters.solver;
  solver_parameters.tolerance = 1e-30;
  const ConstrainedQP &qp = p.qp;
  // x* (computed on another Discretization of the same mesh: the same DoF
  // numbering) on the partitioner of this problem
  LevelVector reference = qp.new_vector();
  reference.copy_locally_owned_data_from(active_set_solution);
  LevelVector              x = qp.new_vector();
  const ConditionalOStream quiet(std::cout, false);
  const double             J_ref    = qp.value(reference);
  double                   distance = std::numeric_limits<double>::max(),
         excess = std::numeric_limits<double>::max();
  bool         decreasing = true, monotone = true;
  unsigned int energy_increases = 0, iterations = 0;
  const auto order = p.discretization.sweep_order(p.discretization.finest_level());
  for (unsigned int b = 0; b < n_batches; ++b)
    {
      Monitor monitor(qp, solver_parameters, quiet, "projected gauss seidel");
      ProjectedGaussSeidel(order).solve(qp, x, monitor);
      energy_increases += monitor.energy_increases();
      iterations += monitor.iterations();
      const auto &history = monitor.get_history();
      for (unsigned int k = 1; k < history.size(); ++k)
        monotone &= history[k].functional.total <=
                    history[k - 1].functional.total +
                      1e-14 * std::abs(history[k - 1].functional.total);

      LevelVector difference(x);
      difference -= reference;
      const double new_distance =
        qp.energy_norm(difference) / qp.energy_norm(reference);
      const double new_excess = (qp.value(x) - J_ref) / std::abs(J_ref);
      decreasing &= new_distance < distance && new_excess < excess &&
                    new_excess >= -1e-12;
      distance = new_distance;
      excess   = new_excess;
    }
  bool same_contact_set = true;
  for (unsigned int i = 0; i < qp.n_owned(); ++i)
    if (qp.role[i] == DoFRole::bounded)
      same_contact_set &=
        (x.local_element(i) == qp.upper_bounds.local_element(i)) ==
        (reference.local_element(i) == qp.upper_bounds.local_element(i));
  std::cout << "sweeps = " << iterations << ", active = " << qp.n_active(x)
            << std::endl;
  check(qp.max_violation(x) == 0., "feasible");
  check(decreasing,
        "|x - x*|_A and J(x) - J(x*) >= 0 decrease from batch to batch");
  check(energy_increases == 0, "Monitor::energy_increases() == 0");
  check(monotone, "J is non-increasing over all sweeps");
  if (std::isfinite(distance_bound))
    check(distance < distance_bound && excess < excess_bound,
          "|x - x*|_A / |x*|_A < " + rounded(distance_bound) +
            ", (J(x) - J(x*)) / J(x*) < " + rounded(excess_bound));
  check(same_contact_set, "same contact set as x*");
}


int
main(int argc, char *argv[])
{
  // MPI first: the mesh is a parallel::distributed::Triangulation, and the
  // reference solver factorizes with Trilinos (Amesos KLU)
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  check_compressed_matrix(5);
  const LevelVector x2 = solve_active_set(2);
  solve_active_set(4);
  // the FOSLS matrix is ill conditioned (diagonally scaled: ~3e4 on 2
  // levels, ~2e5 on 3), so PGS needs many sweeps (rate ~0.9997)
  solve_gauss_seidel(2, x2, 12000, 3, 1e-2, 1e-4);
  // 3 levels: condition ~2e5, only the decrease is checked
  solve_gauss_seidel(3,
                     solve_active_set(3),
                     3000,
                     3,
                     std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity());
  return exit_code();
}
