// ActiveSetDirect where the primal-dual active set method cycles: on the
// problems  minimize 1/2 x^T A x - b^T x  subject to x <= 0  below (A
// symmetric positive definite, not an M-matrix; found by a search over
// random matrices, rounded to integers), the primal-dual method started at
// x = 0 comes back to an earlier active set after 4 steps. The solver must
// continue with its primal active set method and end at the minimizer,
// which is checked against the minimizer found by trying every active set
// (the one feasible point among the 2^3 face minimizers with
// nonnegative multipliers) and by the KKT conditions. Also checked: a
// problem on which the primal-dual method does not cycle gets the same
// answer as before (the fallback is not entered).
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <fosls_contact/solvers/active_set_direct.h>

#include "tests.h"


using namespace FoslsContactTests;

namespace
{
  using Matrix3 = std::vector<std::vector<double>>;

  /** The minimizer by enumeration: every active set, the face's minimizer,
   *  the one that is feasible with nonnegative multipliers. */
  Vector<double>
  enumerated_minimizer(const Matrix3 &A, const std::vector<double> &b)
  {
    for (unsigned int set = 0; set < 8; ++set)
      {
        std::vector<unsigned int> free;
        for (unsigned int i = 0; i < 3; ++i)
          if (!(set & (1u << i)))
            free.push_back(i);
        Vector<double> x(3);
        if (!free.empty())
          {
            FullMatrix<double> M(free.size(), free.size());
            Vector<double>     rhs(free.size()), y(free.size());
            for (unsigned int a = 0; a < free.size(); ++a)
              {
                rhs[a] = b[free[a]];
                for (unsigned int c = 0; c < free.size(); ++c)
                  M(a, c) = A[free[a]][free[c]];
              }
            M.gauss_jordan();
            M.vmult(y, rhs);
            for (unsigned int a = 0; a < free.size(); ++a)
              x[free[a]] = y[a];
          }
        bool kkt = true;
        for (unsigned int i = 0; i < 3; ++i)
          {
            double mu = b[i];
            for (unsigned int j = 0; j < 3; ++j)
              mu -= A[i][j] * x[j];
            kkt &= x[i] <= 1e-14 && ((set & (1u << i)) ? mu >= -1e-14 : true);
          }
        if (kkt)
          return x;
      }
    return Vector<double>();
  }


  void
  test(const std::string &name, const Matrix3 &A_values, const std::vector<double> &b_values)
  {
    const auto          partitioner = serial_partitioner(3);
    DynamicSparsityPattern dsp(3, 3);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        dsp.add(i, j);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> A(pattern);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        A.set(i, j, A_values[i][j]);
    LevelVector b(partitioner), ub(partitioner), x(partitioner);
    for (unsigned int i = 0; i < 3; ++i)
      b.local_element(i) = b_values[i];
    const std::vector<DoFRole> role(3, DoFRole::bounded);

    const bool     converged = ActiveSetDirect::solve_quietly(A, b, role, ub, x, 100);
    const auto     expected  = enumerated_minimizer(A_values, b_values);
    double         difference = 0;
    for (unsigned int i = 0; i < 3; ++i)
      difference = std::max(difference, std::abs(x.local_element(i) - expected[i]));
    std::cout << name << ": x = (" << rounded(x.local_element(0)) << ", "
              << rounded(x.local_element(1)) << ", " << rounded(x.local_element(2)) << ")"
              << std::endl;
    check(converged, name + ": the solver reports convergence");
    check(expected.size() == 3 && difference <= 1e-13 * expected.linfty_norm(),
          name + ": x is the minimizer found by enumeration (1e-13 relative)");
    LevelVector Ax(partitioner);
    A.vmult(Ax, x);
    bool kkt = true;
    for (unsigned int i = 0; i < 3; ++i)
      {
        // (round-off: relative to the terms of the row)
        double row = std::abs(b.local_element(i));
        for (unsigned int j = 0; j < 3; ++j)
          row += std::abs(A_values[i][j] * x.local_element(j));
        const double mu = b.local_element(i) - Ax.local_element(i);
        kkt &= x.local_element(i) <= 0. &&
               (x.local_element(i) == 0. ? mu >= -1e-14 * row : std::abs(mu) <= 1e-14 * row);
      }
    check(kkt, name + ": x <= 0, b - A x = 0 where x < 0 and >= 0 where x = 0 (1e-14 of the row's terms)");
  }
} // namespace


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // the primal-dual method cycles on these: its active sets from x = 0 are
  // {}, {3}, {1, 2, 3}, {2}, then {3} again (found by a search over random
  // matrices, rounded to integers; every indicator mu_i + A_ii (x_i - ub_i)
  // of the steps is at least 1 in magnitude, so round-off plays no part)
  test("cycling, 2 digits", {{232, -171, 126}, {-171, 152, -86}, {126, -86, 85}}, {-67, 60, -1});
  test("cycling, 3 digits",
       {{2315, -1713, 1260}, {-1713, 1524, -857}, {1260, -857, 848}},
       {-668, 596, -15});
  // and converges on this one (an M-matrix)
  test("M-matrix", {{4, -1, 0}, {-1, 4, -1}, {0, -1, 4}}, {1, -2, 1});
  return exit_code();
}
