// Checks CoarseSolver's sparse path (a coarsest level of more than 2000
// DoFs that move), whose factor of the last active set is kept across
// visits of one operator:
//  - every visit gives the active set method's solution bit for bit
//    (ActiveSetDirect on the same problem from the same start);
//  - visits without a finite bound (the linear cycle's) share one
//    factorization; a visit with bounds whose solution has the last
//    visit's active set makes none;
//  - a visit whose active set differs still gives the exact solution
//    (the KKT conditions hold), and a new operator version drops the
//    factor;
//  - fixed DoFs and a bounded DoF with a zero diagonal (switched off by
//    the truncation, its bound infinite) keep their values.
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/coarse_solver.h>

#include "tests.h"

#include <limits>

using namespace FoslsContactTests;

namespace
{
  constexpr unsigned int side = 50; // a side x side grid: 2500 DoFs
  constexpr unsigned int n    = side * side;

  /** The 5-point Laplacian of the grid plus 0.01 times the identity. */
  void
  laplacian(SparsityPattern &pattern, SparseMatrix<double> &A)
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        dsp.add(i, i);
        const unsigned int x = i % side, y = i / side;
        if (x > 0)
          dsp.add(i, i - 1);
        if (x + 1 < side)
          dsp.add(i, i + 1);
        if (y > 0)
          dsp.add(i, i - side);
        if (y + 1 < side)
          dsp.add(i, i + side);
      }
    pattern.copy_from(dsp);
    A.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      for (auto e = A.begin(i); e != A.end(i); ++e)
        e->value() = e->column() == i ? 4.01 : -1.;
  }

  /** The entries where a and b differ (NaN differs from everything) */
  unsigned int
  n_different(const LevelVector &a, const LevelVector &b)
  {
    unsigned int different = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (!(a.local_element(i) == b.local_element(i)))
        ++different;
    return different;
  }

  /** The KKT conditions of min 1/2 v^T A v - r^T v, v <= ub on bounded DoFs */
  bool
  kkt(const SparseMatrix<double> & A,
      const LevelVector &          r,
      const LevelVector &          ub,
      const std::vector<DoFRole> & role,
      const LevelVector &          v)
  {
    LevelVector Av(v.get_partitioner());
    A.vmult(Av, v);
    for (unsigned int i = 0; i < n; ++i)
      {
        if (role[i] == DoFRole::fixed || A.diag_element(i) <= 0.)
          continue;
        const double g = r.local_element(i) - Av.local_element(i);
        if (role[i] == DoFRole::bounded && v.local_element(i) == ub.local_element(i))
          {
            if (g < -1e-12)
              return false;
          }
        else if (std::abs(g) > 1e-12 ||
                 (role[i] == DoFRole::bounded && v.local_element(i) > ub.local_element(i)))
          return false;
      }
    return true;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     inf = std::numeric_limits<double>::infinity();

  SparsityPattern      pattern;
  SparseMatrix<double> A;
  laplacian(pattern, A);
  // a DoF switched off by the truncation: its row and column zero
  const unsigned int off = n / 2 + side / 2;
  for (unsigned int i = 0; i < n; ++i)
    for (auto e = A.begin(i); e != A.end(i); ++e)
      if (i == off || e->column() == off)
        e->value() = 0.;

  // the first row fixed, the last row bounded (a contact boundary)
  std::vector<DoFRole> role(n, DoFRole::free);
  for (unsigned int x = 0; x < side; ++x)
    {
      role[x]            = DoFRole::fixed;
      role[n - side + x] = DoFRole::bounded;
    }
  role[off] = DoFRole::bounded;

  const auto  partitioner = serial_partitioner(n);
  LevelVector r(partitioner), unbounded(partitioner), bounds(partitioner), start(partitioner);
  for (unsigned int i = 0; i < n; ++i)
    {
      r.local_element(i)      = 0.01 * (1. + 0.25 * std::sin(1. + i));
      start.local_element(i)  = role[i] == DoFRole::fixed ? 0.002 : 0.;
      bounds.local_element(i) = role[i] == DoFRole::bounded ? 0.05 + 0.03 * std::cos(0.3 * i) : inf;
    }
  unbounded                 = inf;
  bounds.local_element(off) = inf;
  start.local_element(off)  = 0.125;

  // the active set method's answer from the same start
  const auto reference = [&](const LevelVector &rhs, const LevelVector &ub) {
    LevelVector v(start);
    ActiveSetDirect::solve_quietly(A, rhs, role, ub, v, 100);
    return v;
  };

  CoarseSolver solver;
  unsigned int version = 1;
  const auto   visit   = [&](const LevelVector &rhs, const LevelVector &ub) {
    LevelVector v(start);
    solver.solve(*partitioner, A, version, rhs, ub, role, v);
    return v;
  };

  // three linear visits (the Newton step's linear cycle)
  unsigned int different = 0;
  for (const double scale : {1., -2., 0.5})
    {
      LevelVector rhs(r);
      rhs *= scale;
      different += n_different(visit(rhs, unbounded), reference(rhs, unbounded));
    }
  check(different == 0, "linear visits: the active set method's solution bit for bit");
  check(solver.kept_factorizations() == 1, "linear visits: one factorization for all three");

  // visits with finite bounds: the first finds the active set (one more
  // factorization), the second, a slightly changed load with the same
  // active set, reuses it
  LevelVector bounded_1 = visit(r, bounds);
  LevelVector reference_1 = reference(r, bounds);
  unsigned int held = 0;
  for (unsigned int i = 0; i < n; ++i)
    if (role[i] == DoFRole::bounded && bounded_1.local_element(i) == bounds.local_element(i))
      ++held;
  std::cout << "bounded DoFs at their bound: " << held << " of " << side << std::endl;
  check(held > 0 && held < side, "the bounds are active somewhere, not everywhere");
  check(n_different(bounded_1, reference_1) == 0,
        "a visit with bounds: the active set method's solution bit for bit");
  check(kkt(A, r, bounds, role, bounded_1), "a visit with bounds: the KKT conditions hold");
  const unsigned int after_first = solver.kept_factorizations();
  check(after_first == 2, "a new active set: one more factorization");
  LevelVector r_2(r);
  r_2 *= 1.0001;
  const LevelVector bounded_2 = visit(r_2, bounds);
  check(n_different(bounded_2, reference(r_2, bounds)) == 0,
        "the same active set again: the active set method's solution bit for bit");
  check(solver.kept_factorizations() == after_first, "the same active set: no factorization");
  check(bounded_2.local_element(0) == 0.002 && bounded_2.local_element(off) == 0.125,
        "a fixed DoF and a switched-off DoF keep their values");

  // a load that lifts the DoFs off their bounds: another active set
  LevelVector r_3(r);
  r_3 *= -1.;
  const LevelVector bounded_3 = visit(r_3, bounds);
  check(n_different(bounded_3, reference(r_3, bounds)) == 0 && kkt(A, r_3, bounds, role, bounded_3),
        "another active set: the active set method's solution, KKT");

  // a new operator version: the kept factor is dropped
  ++version;
  const unsigned int before = solver.kept_factorizations();
  visit(r, unbounded);
  check(solver.kept_factorizations() == before + 1, "a new operator version: a new factorization");
  return exit_code();
}
