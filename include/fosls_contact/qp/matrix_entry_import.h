#ifndef fosls_contact_qp_matrix_entry_import_h
#define fosls_contact_qp_matrix_entry_import_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <utility>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Copies of matrix entries whose rows other processes own: the ghost rows
   * a process needs for the vertex patches it relaxes (those of its level
   * matrices, after every change of them) and the entries the flux
   * rerouting reads around a coarse contact face.
   *
   * Which entries is fixed at reinit() (the level patterns do not change),
   * so an import only sends values: each process sends the entries the
   * others asked for, of its own rows, in the order they asked. The matrices
   * are local ones, rows and columns in the local indices of the level's
   * partitioner (LevelVector), and every requested entry must exist in the
   * owner's pattern (checked at reinit()).
   */
  class MatrixEntryImport
  {
  public:
    using Entry = std::pair<types::global_dof_index, types::global_dof_index>;

    /**
     * Ask the owners of the rows of @p requests (global row, global column;
     * rows not owned here) for these entries. @p pattern is this process's
     * local pattern, on which it will answer the others' requests; with
     * @p zero_if_missing an entry outside the owner's pattern is 0 (a
     * matrix on the pattern of its own nonzeros), else an error.
     * Collective over the partitioner's communicator.
     */
    void reinit(const std::vector<Entry> &                                 requests,
                const SparsityPattern &                                    pattern,
                const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                const bool                                                 zero_if_missing = false);

    /**
     * The requested entries, from the owners' @p matrix (every process
     * passes its own matrix on the pattern of reinit()), in the order of
     * the requests. Collective.
     */
    void import(const SparseMatrix<double> &matrix, std::vector<double> &values) const;

    /**
     * For requests in local indices of @p matrix (ghost rows): import and
     * set them in @p matrix.
     */
    void import_into(SparseMatrix<double> &matrix) const;

  private:
    MPI_Comm comm = MPI_COMM_SELF;
    /** The requests in local indices (row, column). */
    std::vector<std::pair<unsigned int, unsigned int>> requests_local;
    /** Per process asked by this one: its rank and the requests (indices). */
    std::vector<std::pair<unsigned int, std::vector<unsigned int>>> receives;
    /** Per process asking this one: its rank and the entries, local (row, column). */
    std::vector<std::pair<unsigned int, std::vector<std::pair<unsigned int, unsigned int>>>>
      sends;
  };
} // namespace FoslsContact

#endif
