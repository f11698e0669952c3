#ifndef fosls_contact_qp_sparse_round_off_h
#define fosls_contact_qp_sparse_round_off_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/qp/level_algebra.h>

#include <functional>
#include <memory>

/**
 * @file
 * The round-off entries of the assembled and Galerkin matrices: couplings
 * that exact arithmetic makes zero but floating point leaves at 1e-15 of
 * the diagonal. They are a quarter of the coupling pattern on fine levels,
 * and every product with the matrix would stream them; these functions
 * find them (relative to the diagonal) and put a matrix on the pattern of
 * what is left.
 */
namespace FoslsContact
{
  /**
   * Set the entries of the owned rows of @p matrix (a local matrix on
   * @p partitioner's indices) with |a_ij| <= drop sqrt(|a_ii a_jj|) to 0
   * (in parallel, by rows). With drop = ConstrainedQP::round_off_drop
   * these are the entries that exact arithmetic makes zero: couplings that
   * cancel in the assembly of A, or in a Galerkin product of it. The
   * diagonal of the ghost columns comes from their owners.
   *
   * @p part, if given, is a part of @p matrix assembled on its own (the
   * equilibrium term), on a pattern within that of @p matrix, whose
   * entries are exact zeros where it does not couple two DoFs. The round-off of a_ij is then
   * bounded by the parts that have the entry: the threshold is
   * drop (sqrt(|p_ii p_jj|) [p_ij != 0] + sqrt(|r_ii r_jj|)), r = A - p,
   * which is at most drop sqrt(|a_ii a_jj|). This matters where the parts
   * scale apart: the equilibrium diagonal of an RT flux grows like
   * C_eq h^-2, the constitutive couplings of two stress rows stay O(1),
   * so that sqrt(a_ii a_jj) 1e-13 exceeds these genuine couplings on
   * cells of 2^-17 of the domain (an adaptive mesh at a re-entrant corner)
   * or at level 8 with C_eq = 1e8, and dropping them made A indefinite
   * (tests/solver/singular_corner).
   */
  void zero_round_off(SparseMatrix<double> &                                     matrix,
                      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                      const double                                               drop,
                      const SparseMatrix<double> *                               part = nullptr);

  /**
   * The diagonal of a local matrix (owned rows), with its ghost values:
   * the diagonal entries of the ghost DoFs, from their owners.
   */
  LevelVector diagonal(const SparseMatrix<double> &                                matrix,
                       const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner);

  /**
   * Put @p matrix on @p sparsity, the pattern of its nonzero entries (and
   * the diagonal). The pattern is built in place from exact row lengths
   * (a DynamicSparsityPattern and a list of (column, value) pairs cost 2.5
   * times more at level 9 of the square), the kept values are moved to the
   * front of the old value array, and then copied into the new matrix, so
   * that the peak is the old matrix plus the new one.
   *
   * @p release_old_pattern, if given, is called when the old pattern is no
   * longer read, before the new values are allocated: a caller that owns
   * that pattern and needs it no more can free its arrays there (the old
   * matrix is replaced right after without reading it), so that the old
   * pattern and the new values are never held at once (on the largest
   * meshes the old pattern is gigabytes).
   */
  void compress_to_nonzeros(SparseMatrix<double> &        matrix,
                            SparsityPattern &             sparsity,
                            const std::function<void()> &release_old_pattern = {});
} // namespace FoslsContact

#endif
