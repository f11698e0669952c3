#include <fosls_contact/solvers/galerkin_product.h>

#include <deal.II/base/parallel.h>
#include <deal.II/base/thread_local_storage.h>

namespace FoslsContact
{
  void
  GalerkinProduct::initialize(const SparsityPattern &pattern)
  {
    n_coarse = pattern.n_cols();
    transpose_start.assign(n_coarse + 1, 0);
    for (auto e = pattern.begin(); e != pattern.end(); ++e)
      ++transpose_start[e->column() + 1];
    for (unsigned int j = 0; j < n_coarse; ++j)
      transpose_start[j + 1] += transpose_start[j];
    transpose_row.resize(transpose_start.back());
    transpose_position.resize(transpose_start.back());
    std::vector<std::size_t> next(transpose_start.begin(), transpose_start.end() - 1);
    for (auto e = pattern.begin(); e != pattern.end(); ++e)
      {
        const auto k           = next[e->column()]++;
        transpose_row[k]       = e->row();
        transpose_position[k]  = e->global_index();
      }
  }


  void
  GalerkinProduct::compute(const SparseMatrix<double> &A,
                           const SparseMatrix<double> &P,
                           SparseMatrix<double> &      product,
                           SparseMatrix<double> &      galerkin)
  {
    // the values of P in the order of its pattern (global_index)
    const SparsityPattern &P_pattern = P.get_sparsity_pattern();
    P_values.resize(P_pattern.n_nonzero_elements());
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(P.m()),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int r = begin; r < end; ++r)
          for (auto e = P.begin(r); e != P.end(r); ++e)
            P_values[e->global_index()] = e->value();
      },
      1000);

    // a dense row of length n_coarse per thread, kept zero between rows
    Threads::ThreadLocalStorage<std::vector<double>> dense_row(
      std::vector<double>(n_coarse, 0.));

    // product = A P, row by row
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(A.m()),
      [&](const unsigned int begin, const unsigned int end) {
        std::vector<double> &row = dense_row.get();
        for (unsigned int r = begin; r < end; ++r)
          {
            for (auto a = A.begin(r); a != A.end(r); ++a)
              if (a->value() != 0.)
                for (auto p = P.begin(a->column()); p != P.end(a->column()); ++p)
                  row[p->column()] += a->value() * P_values[p->global_index()];
            for (auto e = product.begin(r); e != product.end(r); ++e)
              {
                e->value()       = row[e->column()];
                row[e->column()] = 0.;
              }
          }
      },
      200);

    // galerkin = P^T product, row j from the rows of product at column j
    // of P
    parallel::apply_to_subranges(
      0u,
      n_coarse,
      [&](const unsigned int begin, const unsigned int end) {
        std::vector<double> &row = dense_row.get();
        for (unsigned int j = begin; j < end; ++j)
          {
            for (std::size_t k = transpose_start[j]; k < transpose_start[j + 1]; ++k)
              {
                const double p = P_values[transpose_position[k]];
                if (p != 0.)
                  {
                    const unsigned int r = transpose_row[k];
                    for (auto e = product.begin(r); e != product.end(r); ++e)
                      row[e->column()] += p * e->value();
                  }
              }
            for (auto e = galerkin.begin(j); e != galerkin.end(j); ++e)
              {
                e->value()       = row[e->column()];
                row[e->column()] = 0.;
              }
          }
      },
      100);
  }


  void
  GalerkinProduct::Tvmult(Vector<double> &dst, const Vector<double> &src) const
  {
    AssertDimension(dst.size(), n_coarse);
    parallel::apply_to_subranges(
      0u,
      n_coarse,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int j = begin; j < end; ++j)
          {
            double sum = 0;
            for (std::size_t k = transpose_start[j]; k < transpose_start[j + 1]; ++k)
              sum += P_values[transpose_position[k]] * src[transpose_row[k]];
            dst[j] = sum;
          }
      },
      500);
  }
} // namespace FoslsContact
