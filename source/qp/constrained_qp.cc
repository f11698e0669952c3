#include <fosls_contact/qp/constrained_qp.h>

#include <deal.II/base/parallel.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace FoslsContact
{
  void
  ConstrainedQP::reinit(const AlgebraicLevel &level)
  {
    matrix.reinit(level.sparsity);
    matrix_eq.reinit(level.sparsity);
    matrix_compl.reinit(level.sparsity);
    partitioner = level.partitioner;
    ghost_rows  = &level.ghost_rows;
    rhs.reinit(partitioner);
    rhs_eq.reinit(partitioner);
    rhs_compl.reinit(partitioner);
    constant = constant_eq = 0;
    coupling_sparsity = &level.sparsity;
    role         = level.role;
    dimension    = level.dimension;
    fixed_values = level.fixed_values;
    upper_bounds = level.upper_bounds;
    update_ghosts(fixed_values);
    update_ghosts(upper_bounds);
  }


  namespace
  {
    /**
     * Put @p matrix on @p sparsity, the pattern of its nonzero entries (and
     * the diagonal). The pattern is built in place from exact row lengths
     * and the kept values are staged in one array, so that the peak is the
     * old matrix plus the new one: a DynamicSparsityPattern and a list of
     * (column, value) pairs cost 2.5 times more at level 9 of the square.
     */
    void
    compress(SparseMatrix<double> &matrix, SparsityPattern &sparsity)
    {
      Assert(&matrix.get_sparsity_pattern() != &sparsity, ExcInternalError());
      const auto n    = matrix.m();
      const auto kept = [](const auto &entry) {
        return entry.value() != 0. || entry.column() == entry.row();
      };
      std::vector<unsigned int> row_lengths(n, 0);
      for (types::global_dof_index i = 0; i < n; ++i)
        row_lengths[i] = std::count_if(matrix.begin(i), matrix.end(i), kept);
      sparsity.reinit(n, n, row_lengths);
      for (types::global_dof_index i = 0; i < n; ++i)
        for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
          if (kept(*e))
            sparsity.add(i, e->column());
      sparsity.compress();

      // Both patterns store a row as the diagonal and then the other
      // columns in increasing order, so a new row is a subsequence of the
      // old one.
      std::vector<double> values;
      values.reserve(sparsity.n_nonzero_elements());
      for (types::global_dof_index i = 0; i < n; ++i)
        {
          auto e = matrix.begin(i);
          for (auto s = sparsity.begin(i); s != sparsity.end(i); ++s)
            {
              while (e->column() != s->column())
                ++e;
              values.push_back(e->value());
            }
        }
      // clear() first: SparseMatrix::reinit keeps an allocation that is
      // large enough, which would be that of the full pattern
      matrix.clear();
      matrix.reinit(sparsity);
      std::size_t k = 0;
      for (types::global_dof_index i = 0; i < n; ++i)
        for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
          e->value() = values[k++];
    }
  } // namespace


  LevelVector
  diagonal(const SparseMatrix<double> &                                matrix,
           const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
  {
    LevelVector d(partitioner);
    for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
      d.local_element(i) = matrix.diag_element(i);
    update_ghosts(d);
    return d;
  }


  void
  zero_round_off(SparseMatrix<double> &                                     matrix,
                 const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                 const double                                               drop)
  {
    // The rule treats a_ij and a_ji alike, so a symmetric pattern stays
    // symmetric unless one of them is within round-off of the threshold
    // (measured on A: all entries are below 1e-15 or above 1e-8 of
    // sqrt(a_ii a_jj); the patch colors do not rely on symmetry).
    const LevelVector   d = diagonal(matrix, partitioner);
    std::vector<double> root_diagonal(d.locally_owned_size() + partitioner->n_ghost_indices());
    for (unsigned int i = 0; i < root_diagonal.size(); ++i)
      root_diagonal[i] = std::sqrt(std::abs(d.local_element(i)));
    for_subranges(
      0u,
      partitioner->locally_owned_size(),
      [&](const unsigned int begin, const unsigned int end) {
        for (auto i = begin; i < end; ++i)
          for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
            if (std::abs(e->value()) <= drop * root_diagonal[i] * root_diagonal[e->column()])
              e->value() = 0.;
      },
      500);
  }


  void
  ConstrainedQP::compress_matrices()
  {
    zero_round_off(matrix, partitioner, round_off_drop);
    ghost_rows->import_into(matrix);
    // the small parts first: the memory they free takes A's new pattern
    // (freed memory stays with the process, measured: the resident memory
    // does not drop when the full-pattern values are freed)
    compress(matrix_eq, sparsity_eq);
    compress(matrix_compl, sparsity_compl);
    compress(matrix, sparsity);
  }


  namespace
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
    double
    accurate_quadratic(const SparseMatrix<double> &M,
                       const LevelVector &         x,
                       const LevelVector &         b,
                       const double                c)
    {
      update_ghosts(x);
      const auto partial = sum_over_row_blocks<CompensatedSum>(
        x.locally_owned_size(), [&](CompensatedSum &sum, const unsigned int i) {
          // (M x)_i in twice the precision, times x_i / 2
          const double   xi = x.local_element(i);
          CompensatedSum row;
          for (auto e = M.begin(i); e != M.end(i); ++e)
            row.add_product(e->value(), x.local_element(e->column()));
          sum.add_product(0.5 * xi, row.sum);
          sum.add(0.5 * xi * row.error);
          sum.add_product(-b.local_element(i), xi);
        });
      CompensatedSum local;
      for (const auto &p : partial)
        local.add(p);
      // the processes' sums, added in the order of the ranks (the same on
      // every process)
      const auto all = gather_all(x.get_mpi_communicator(),
                                  std::array<double, 2>{{local.sum, local.error}});
      CompensatedSum total;
      for (const auto &[sum, error] : all)
        {
          total.add(sum);
          total.error += error;
        }
      total.add(c);
      return total.value();
    }
  } // namespace


  double
  ConstrainedQP::value(const LevelVector &x) const
  {
    return accurate_quadratic(matrix, x, rhs, constant);
  }


  FunctionalValue
  ConstrainedQP::parts(const LevelVector &x) const
  {
    FunctionalValue v;
    v.total = value(x);
    v.eq    = accurate_quadratic(matrix_eq, x, rhs_eq, constant_eq);
    v.complementarity = accurate_quadratic(matrix_compl, x, rhs_compl, 0.);
    v.constitutive    = v.total - v.eq - v.complementarity;
    return v;
  }


  void
  ConstrainedQP::project_to_feasible(LevelVector &x) const
  {
    for (unsigned int i = 0; i < role.size(); ++i)
      if (role[i] == DoFRole::fixed)
        x.local_element(i) = fixed_values.local_element(i);
      else if (role[i] == DoFRole::bounded)
        x.local_element(i) = std::min(x.local_element(i), upper_bounds.local_element(i));
  }


  double
  ConstrainedQP::max_violation(const LevelVector &x) const
  {
    double v = 0;
    for (unsigned int i = 0; i < n_owned(); ++i)
      if (role[i] == DoFRole::fixed)
        v = std::max(v, std::abs(x.local_element(i) - fixed_values.local_element(i)));
      else if (role[i] == DoFRole::bounded)
        v = std::max(v, x.local_element(i) - upper_bounds.local_element(i));
    return Utilities::MPI::max(v, get_communicator());
  }


  std::vector<bool>
  ConstrainedQP::active_set(const LevelVector &x) const
  {
    std::vector<bool> active(n_owned(), false);
    for (unsigned int i = 0; i < n_owned(); ++i)
      active[i] = role[i] == DoFRole::bounded &&
                  x.local_element(i) >= upper_bounds.local_element(i);
    return active;
  }


  unsigned int
  ConstrainedQP::n_active(const std::vector<bool> &active) const
  {
    return Utilities::MPI::sum(
      static_cast<unsigned int>(std::count(active.begin(), active.end(), true)),
      get_communicator());
  }


  unsigned int
  ConstrainedQP::n_active(const LevelVector &x) const
  {
    return n_active(active_set(x));
  }


  KKTResidual
  ConstrainedQP::kkt_residual(const LevelVector &x) const
  {
    // For x_i <= ub_i the multiplier is mu_i = (b - A x)_i >= 0; it must
    // vanish where the bound is not attained.
    LevelVector g = new_vector();
    vmult(matrix, g, x);
    g -= rhs;
    // relative to the size of the terms of each row, sum_j |A_ij x_j|, so
    // that the residual is meaningful also when b = 0 (pure Dirichlet data)
    double scale = rhs.linfty_norm();
    double local_scale = 0, bound_scale = 1;
    for (unsigned int i = 0; i < n_owned(); ++i)
      {
        if (role[i] != DoFRole::fixed)
          {
            double row = 0;
            for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
              row += std::abs(e->value() * x.local_element(e->column()));
            local_scale = std::max(local_scale, row);
          }
        if (role[i] == DoFRole::bounded)
          bound_scale = std::max(bound_scale, std::abs(upper_bounds.local_element(i)));
      }
    const MPI_Comm comm = get_communicator();
    scale       = std::max(std::max(scale, Utilities::MPI::max(local_scale, comm)), 1e-300);
    bound_scale = Utilities::MPI::max(bound_scale, comm);

    KKTResidual r;
    for (unsigned int i = 0; i < n_owned(); ++i)
      {
        const double gi = g.local_element(i), xi = x.local_element(i);
        switch (role[i])
          {
            case DoFRole::free:
              r.stationarity = std::max(r.stationarity, std::abs(gi));
              break;
            case DoFRole::fixed:
              r.feasibility = std::max(r.feasibility,
                                       std::abs(xi - fixed_values.local_element(i)) / bound_scale);
              break;
            case DoFRole::bounded:
              {
                const double ub = upper_bounds.local_element(i);
                const double mu = std::max(0., -gi);
                r.stationarity  = std::max(r.stationarity, std::max(0., gi));
                r.feasibility =
                  std::max(r.feasibility, std::max(0., xi - ub) / bound_scale);
                r.complementarity =
                  std::max(r.complementarity, mu * std::abs(ub - xi) / bound_scale);
                break;
              }
          }
      }
    r.stationarity    = Utilities::MPI::max(r.stationarity, comm) / scale;
    r.feasibility     = Utilities::MPI::max(r.feasibility, comm);
    r.complementarity = Utilities::MPI::max(r.complementarity, comm) / scale;
    return r;
  }


  double
  ConstrainedQP::energy_norm(const LevelVector &d) const
  {
    return std::sqrt(std::max(0., matrix_norm_square(matrix, d)));
  }


  double
  ConstrainedQP::round_off_correction(const LevelVector &x) const
  {
    update_ghosts(x);
    const auto partial = sum_over_row_blocks<double>(
      n_owned(), [&](double &sum, const unsigned int i) {
        if (role[i] != DoFRole::fixed && matrix.diag_element(i) > 0)
          {
            double s = std::abs(rhs.local_element(i));
            for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
              s += std::abs(e->value() * x.local_element(e->column()));
            sum += s * s / matrix.diag_element(i);
          }
      });
    double sum = 0;
    for (const double p : partial)
      sum += p;
    sum = Utilities::MPI::sum(sum, get_communicator());
    return std::numeric_limits<double>::epsilon() * std::sqrt(sum) *
           std::pow(double(x.size()), 1. / dimension);
  }
} // namespace FoslsContact
