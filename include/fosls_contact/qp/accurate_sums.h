#ifndef fosls_contact_qp_accurate_sums_h
#define fosls_contact_qp_accurate_sums_h

#include <deal.II/base/parallel.h>
#include <deal.II/lac/sparse_matrix.h>

#include <fosls_contact/qp/level_algebra.h>

#include <algorithm>
#include <cmath>
#include <vector>

/**
 * @file
 * Sums over the rows of a level that do not depend on the number of
 * threads or processes and, for the functional, carry twice the working
 * precision: the monotone solvers compare values of J that agree to 1e-8
 * relative, and a sum that changed with the threads or lost those digits
 * would show spurious increases of J.
 */
namespace FoslsContact
{
  /**
   * A sum in twice the working precision (Ogita, Rump, Oishi: Sum2 and
   * Dot2): the rounding errors of every addition (two_sum) and product
   * (two_product, with a fused multiply-add) are collected in a second
   * double.
   */
  struct CompensatedSum
  {
    double sum = 0, error = 0;

    void
    add(const double a)
    {
      const double s = sum + a;
      const double b = s - sum;
      error += (sum - (s - b)) + (a - b);
      sum = s;
    }
    void
    add_product(const double a, const double b)
    {
      const double p = a * b;
      add(p);
      error += std::fma(a, b, -p);
    }
    void
    add(const CompensatedSum &other)
    {
      add(other.sum);
      error += other.error;
    }
    double value() const { return sum + error; }
  };


  /**
   * The rows of one block of sum_over_row_blocks(): fixed, so that the
   * order of the sums does not depend on the threads; large enough that
   * a block outweighs the start-up of its task.
   */
  constexpr types::global_dof_index rows_per_block = 512;


  /**
   * Partial sums add_row(partial, i) over fixed blocks of rows, computed
   * in parallel; the caller adds them in order, so that the result does
   * not depend on the number of threads.
   */
  template <typename T, typename Function>
  std::vector<T>
  sum_over_row_blocks(const unsigned int n, const Function &add_row)
  {
    constexpr types::global_dof_index block = rows_per_block;
    std::vector<T>                partial((n + block - 1) / block, T());
    for_subranges(
      types::global_dof_index(0),
      types::global_dof_index(partial.size()),
      [&](const types::global_dof_index begin, const types::global_dof_index end) {
        for (auto k = begin; k < end; ++k)
          for (auto i = k * block; i < std::min(n, (k + 1) * block); ++i)
            add_row(partial[k], i);
      },
      1);
    return partial;
  }


  /**
   * 1/2 x^T M x - b^T x + c, accurate to about the last digit of the
   * result. At a converged iterate the terms of x^T M x are many orders
   * of magnitude larger than the functional (the entries of M grow like
   * C_eq / h^2, and x holds the Dirichlet values): in plain double
   * precision the value carried an error of 1e-8 of J itself on the
   * graded half disc, enough to show a spurious increase of J in
   * convergence.csv. Rows are summed in fixed blocks (in parallel) and
   * the block sums added in order, so the value does not depend on the
   * number of threads.
   */
  double accurate_quadratic(const SparseMatrix<double> &M,
                            const LevelVector &         x,
                            const LevelVector &         b,
                            const double                c);

  /**
   * Row i's terms of accurate_quadratic(), added to @p sum: x_i (M x)_i / 2
   * (@p Mx_i, summed with its error) - b_i x_i.
   */
  inline void
  add_quadratic_row(CompensatedSum &      sum,
                    const double          x_i,
                    const CompensatedSum &Mx_i,
                    const double          b_i)
  {
    sum.add_product(0.5 * x_i, Mx_i.sum);
    sum.add(0.5 * x_i * Mx_i.error);
    sum.add_product(-b_i, x_i);
  }

  /**
   * The end of accurate_quadratic(): this process's sum of the blocks,
   * @p local, added to the other processes' in the order of the ranks (the
   * same on every process), plus @p c. Collective.
   */
  double
  accurate_total(const CompensatedSum &local, const MPI_Comm comm, const double c);
} // namespace FoslsContact

#endif
