#include <deal.II/base/memory_consumption.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/solvers/level_operators.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  namespace
  {
    /** Rows per task of the loops over the rows of P~. */
    constexpr unsigned int row_grain = 1000;
  } // namespace


  template <int dim>
  LevelOperators<dim>::LevelOperators(const MultilevelHierarchy<dim> &hierarchy,
                                      const SparsityPattern &         fine_sparsity,
                                      FluxRerouting<dim> &            rerouting)
    : hierarchy(hierarchy)
    , rerouting(rerouting)
    , finest(hierarchy.finest_level())
    , prolongation_sparsity(finest + 1)
    , prolongation(finest + 1)
    , product(finest + 1)
    , coarse(finest + 1)
    , truncation_used(finest + 1)
    , version(finest + 1, 0)
    , version_used(finest + 1, numbers::invalid_unsigned_int)
    , reroute_used(finest + 1, false)
  {
    // the results of the Galerkin products lie on the coupling patterns
    // of the coarse levels; the solve only recomputes values
    for (unsigned int l = finest; l > 0; --l)
      {
        const auto &           fine = hierarchy.level(l), &coarser = hierarchy.level(l - 1);
        const SparsityPattern &A  = l == finest ? fine_sparsity : fine.sparsity;
        const SparsityPattern &P0 = hierarchy.prolongation(l).get_sparsity_pattern();
        DynamicSparsityPattern dsp(P0.n_rows(), P0.n_cols());
        // (by rows: an iterator's row() searches for its row)
        for (unsigned int i = 0; i < P0.n_rows(); ++i)
          for (auto e = P0.begin(i); e != P0.end(i); ++e)
            dsp.add(i, e->column());
        for (const auto &[i, j] : hierarchy.rerouting_entries(l))
          dsp.add(i, j);
        prolongation_sparsity[l].copy_from(dsp);
        prolongation[l].reinit(prolongation_sparsity[l]);
        product[l].initialize(
          prolongation_sparsity[l], A, fine.partitioner, coarser.sparsity, coarser.partitioner);
        coarse[l - 1].reinit(coarser.sparsity);
      }
  }


  template <int dim>
  void
  LevelOperators<dim>::new_fine_operator(const SparseMatrix<double> &A)
  {
    ++version[finest];
    rerouting.import_values(finest, A);
  }


  template <int dim>
  bool
  LevelOperators<dim>::needs_update(const unsigned int       l,
                                    const std::vector<bool> &truncated,
                                    const bool               reroute) const
  {
    // (truncation_used[l] is empty until the first product); every process
    // takes part in the products, so the decision is taken together
    const bool unchanged = truncated == truncation_used[l] && version[l] == version_used[l] &&
                           reroute == reroute_used[l];
    const MPI_Comm comm = hierarchy.level(l).partitioner->get_mpi_communicator();
    return Utilities::MPI::min(unchanged ? 1u : 0u, comm) == 0;
  }


  template <int dim>
  void
  LevelOperators<dim>::truncate_rows(const unsigned int l, const std::vector<bool> &truncated)
  {
    // (P~'s pattern holds P's and the entries flux rerouting may add;
    // both sorted by column)
    SparseMatrix<double> &      Pt = prolongation[l];
    const SparseMatrix<double> &P  = hierarchy.prolongation(l);
    for_subranges(
      types::global_dof_index(0),
      types::global_dof_index(P.m()),
      [&](const types::global_dof_index begin, const types::global_dof_index end) {
        for (auto r = begin; r < end; ++r)
          {
            auto p = P.begin(r);
            for (auto e = Pt.begin(r); e != Pt.end(r); ++e)
              if (!truncated[r] && p != P.end(r) && p->column() == e->column())
                {
                  e->value() = p->value();
                  ++p;
                }
              else
                e->value() = 0.;
          }
      },
      row_grain);
  }


  template <int dim>
  void
  LevelOperators<dim>::apply_face_changes(
    const unsigned int                                           l,
    const std::vector<types::global_dof_index> &                 removed,
    const std::vector<typename FluxRerouting<dim>::ColumnEntry> &entries)
  {
    SparseMatrix<double> &Pt      = prolongation[l];
    const auto &          fine    = *hierarchy.level(l).partitioner;
    const auto &          coarser = *hierarchy.level(l - 1).partitioner;
    const MPI_Comm        comm    = fine.get_mpi_communicator();
    auto                  here    = [](const Utilities::MPI::Partitioner &p,
                     const types::global_dof_index      i) {
      return p.in_local_range(i) || p.is_ghost_entry(i);
    };
    std::vector<bool> removed_local(Pt.n(), false);
    for (const auto &list : gather_all(comm, removed))
      for (const auto j : list)
        if (here(coarser, j))
          removed_local[coarser.global_to_local(j)] = true;
    for (const auto &list : gather_all(comm, entries))
      for (const auto &[row, column, value] : list)
        {
          const auto i = static_cast<types::global_dof_index>(row);
          const auto j = static_cast<types::global_dof_index>(column);
          if (here(fine, i) && here(coarser, j))
            Pt.add(fine.global_to_local(i), coarser.global_to_local(j), value);
        }
    for_subranges(
      types::global_dof_index(0),
      types::global_dof_index(Pt.m()),
      [&](const types::global_dof_index begin, const types::global_dof_index end) {
        for (auto r = begin; r < end; ++r)
          for (auto e = Pt.begin(r); e != Pt.end(r); ++e)
            if (removed_local[e->column()])
              e->value() = 0.;
      },
      row_grain);
  }


  template <int dim>
  void
  LevelOperators<dim>::update(const unsigned int          l,
                              const SparseMatrix<double> &A,
                              const std::vector<DoFRole> &role,
                              const std::vector<bool> &   truncated,
                              const bool                  reroute)
  {
    truncate_rows(l, truncated);
    // the coarse faces that go, and the rerouted columns, are decided by
    // the owners of the faces and applied by every process to its rows
    std::vector<types::global_dof_index>                  removed;
    std::vector<typename FluxRerouting<dim>::ColumnEntry> entries;
    if (reroute)
      rerouting.reroute(l, A, hierarchy.prolongation(l), role, truncated, removed, entries);
    else
      rerouting.linear_columns(l, A, hierarchy.prolongation(l), role, truncated, removed, entries);
    apply_face_changes(l, removed, entries);

    const auto &coarser = hierarchy.level(l - 1);
    product[l].compute(A, prolongation[l], coarse[l - 1]);
    // the couplings of coarse functions whose fine couplings cancel (a
    // sixth of the product's nonzeros on the square) would lengthen the
    // patch residuals
    zero_round_off(coarse[l - 1], coarser.partitioner, ConstrainedQP::round_off_drop);
    coarser.ghost_rows.import_into(coarse[l - 1]);
    rerouting.import_values(l - 1, coarse[l - 1]);
    truncation_used[l] = truncated;
    version_used[l]    = version[l];
    reroute_used[l]    = reroute;
    ++version[l - 1];
  }


  template <int dim>
  void
  LevelOperators<dim>::restrict_defect(const unsigned int          l,
                                       const SparseMatrix<double> &A,
                                       const LevelVector &         r,
                                       const LevelVector &         v,
                                       LevelVector &               residual,
                                       LevelVector &               r_coarse,
                                       const PairTerms *           pair_terms) const
  {
    vmult(A, residual, v, false); // (v's ghosts: valid in a visit)
    residual.sadd(-1., 1., r);
    if (pair_terms != nullptr)
      pair_terms->subtract_product(v, residual);
    product[l].Tvmult(r_coarse, residual);
  }


  template <int dim>
  double
  LevelOperators<dim>::coarse_defect_difference(const unsigned int          l,
                                                const SparseMatrix<double> &A,
                                                const LevelVector &         r,
                                                const LevelVector &         v,
                                                const LevelVector &         r_coarse) const
  {
    LevelVector residual(r), difference(r_coarse);
    restrict_defect(l, A, r, v, residual, difference);
    difference -= r_coarse;
    const MPI_Comm comm = r.get_partitioner()->get_mpi_communicator();
    const double   bound =
      Utilities::MPI::max(prolongation[l].l1_norm(), comm) *
      (Utilities::MPI::max(A.linfty_norm(), comm) * v.linfty_norm() + r.linfty_norm());
    // (linfty_norm() may drop a NaN, the l2 norm keeps it)
    const double size = difference.l2_norm();
    return !std::isfinite(size) || !std::isfinite(bound) ?
             std::numeric_limits<double>::quiet_NaN() :
           bound > 0 ? difference.linfty_norm() / bound :
           size > 0  ? std::numeric_limits<double>::infinity() :
                       0.;
  }

  template <int dim>
  LevelBytes
  LevelOperators<dim>::product_memory_consumption() const
  {
    LevelBytes bytes;
    for (const GalerkinProduct &p : product)
      bytes.push_back(p.memory_consumption());
    return bytes;
  }


  template <int dim>
  LevelBytes
  LevelOperators<dim>::memory_consumption() const
  {
    LevelBytes bytes(std::max(coarse.size(), prolongation.size()), 0);
    for (unsigned int l = 0; l < coarse.size(); ++l)
      bytes[l] += coarse[l].memory_consumption();
    for (unsigned int l = 0; l < prolongation.size(); ++l)
      bytes[l] +=
        prolongation[l].memory_consumption() + prolongation_sparsity[l].memory_consumption();
    return bytes;
  }

  template class LevelOperators<2>;
  template class LevelOperators<3>;
} // namespace FoslsContact
