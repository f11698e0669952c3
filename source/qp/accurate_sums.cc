#include <fosls_contact/qp/accurate_sums.h>

#include <array>

namespace FoslsContact
{
  double
  accurate_quadratic(const SparseMatrix<double> &M,
                     const LevelVector &         x,
                     const LevelVector &         b,
                     const double                c)
  {
    update_ghosts(x);
    const LocalElements x_local(x); // (the ghost entries too: see LocalElements)
    const auto          partial = sum_over_row_blocks<CompensatedSum>(
      x.locally_owned_size(), [&](CompensatedSum &sum, const unsigned int i) {
        // (M x)_i in twice the precision
        CompensatedSum row;
        for (auto e = M.begin(i); e != M.end(i); ++e)
          row.add_product(e->value(), x_local(e->column()));
        add_quadratic_row(sum, x.local_element(i), row, b.local_element(i));
      });
    CompensatedSum local;
    for (const auto &p : partial)
      local.add(p);
    return accurate_total(local, x.get_mpi_communicator(), c);
  }


  double
  accurate_total(const CompensatedSum &local, const MPI_Comm comm, const double c)
  {
    const auto all = gather_all(comm, std::array<double, 2>{{local.sum, local.error}});
    CompensatedSum total;
    for (const auto &[sum, error] : all)
      {
        total.add(sum);
        total.error += error;
      }
    total.add(c);
    return total.value();
  }
} // namespace FoslsContact
