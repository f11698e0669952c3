#ifndef fosls_contact_qp_matrix_list_memory_h
#define fosls_contact_qp_matrix_list_memory_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The bytes of a list of matrices, each on its own pattern (entry l of
   * both lists; an empty entry where a level has none): the prolongations
   * of LevelTransfer and LevelMeshes, the rotated prolongations of
   * MultilevelHierarchy.
   */
  inline std::size_t
  matrix_list_memory_consumption(const std::vector<std::unique_ptr<SparseMatrix<double>>> &matrices,
                                 const std::vector<std::unique_ptr<SparsityPattern>> &patterns)
  {
    std::size_t bytes = 0;
    for (std::size_t l = 0; l < matrices.size(); ++l)
      if (matrices[l])
        bytes += matrices[l]->memory_consumption() + patterns[l]->memory_consumption();
    return bytes;
  }
} // namespace FoslsContact

#endif
