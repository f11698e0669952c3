#ifndef fosls_contact_qp_matrix_list_memory_h
#define fosls_contact_qp_matrix_list_memory_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <cstddef>
#include <memory>
#include <numeric>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Bytes by multigrid level: entry l is what a structure holds for level
   * l (a prolongation or a Galerkin product counts on the finer level it
   * maps into or from). summary.json's `memory_mb_by_level` shows where
   * the memory of a run goes level by level: the finest level's share
   * against that of the coarser ones together.
   */
  using LevelBytes = std::vector<std::size_t>;

  /** The bytes of all levels together. */
  inline std::size_t
  total_bytes(const LevelBytes &bytes)
  {
    return std::accumulate(bytes.begin(), bytes.end(), std::size_t(0));
  }

  /**
   * The bytes of a list of matrices, each on its own pattern (entry l of
   * both lists; an empty entry where a level has none), by level: the
   * prolongations of LevelTransfer and LevelMeshes, the rotated
   * prolongations of MultilevelHierarchy.
   */
  inline LevelBytes
  matrix_list_memory_consumption(const std::vector<std::unique_ptr<SparseMatrix<double>>> &matrices,
                                 const std::vector<std::unique_ptr<SparsityPattern>> &patterns)
  {
    LevelBytes bytes(matrices.size(), 0);
    for (std::size_t l = 0; l < matrices.size(); ++l)
      if (matrices[l])
        bytes[l] = matrices[l]->memory_consumption() + patterns[l]->memory_consumption();
    return bytes;
  }
} // namespace FoslsContact

#endif
