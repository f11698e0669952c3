#ifndef fosls_contact_solvers_packed_patches_h
#define fosls_contact_solvers_packed_patches_h

#include <deal.II/base/aligned_vector.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparse_matrix.h>

#include <fosls_contact/qp/dof_role.h>
#include <fosls_contact/solvers/box_qp.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace FoslsContact
{
  /**
   * The vertex patches of one level, packed for the sweeps of the
   * PatchSmoother: their DoFs, a copy of their matrix rows and the inverse
   * of every patch matrix, in sweep order, color by color. A sweep streams
   * through these arrays in order, and from level 8 of the square on they
   * no longer fit in cache (240 MB at level 9, against 110 MB for the
   * matrix), so their size is the time of a sweep there:
   * - patch k has n = start[k+1] - start[k] DoFs; its neighbourhood, the
   *   columns of its rows, is neighbors[neighbor_start[k] ..
   *   neighbor_start[k+1]), the patch DoFs first;
   * - its rows are copied next to each other (row_start, columns, values;
   *   a row of a face DoF appears in the two patches of the face's end
   *   points), so that the patch residual reads one contiguous block
   *   instead of jumping through the sparse matrix. The columns are 16-bit
   *   positions in the neighbourhood, whose values a relaxation gathers
   *   first (against 32-bit DoF indices: 15% less data);
   * - the inverse of its matrix is stored as its upper triangle by rows at
   *   inverse[inverse_start[k] ..) (n (n+1)/2 entries instead of n^2);
   * - only patches with a bounded DoF can hit an obstacle, so only they
   *   keep a BoxQP for the constrained case (box_qp[k], an index into qps).
   *
   * The patches of color c are color_start[c] .. color_start[c+1]. The
   * large arrays are AlignedVectors, whose resize_fast() leaves new
   * entries uninitialized for the parallel fill of build().
   */
  struct PackedPatches
  {
    /**
     * Pack the @p patches of a level (local DoFs, in the order of the
     * sweep) with their colors for @p matrix (whose rows are copied: a
     * changed matrix needs a new call). Fixed DoFs and DoFs with a zero
     * diagonal (switched off by the truncation of the finer level) are
     * left out of every patch, and a patch without any other DoF is
     * dropped. Refuses colors under which the matrix couples two patches
     * of one color. Rows are stored with their columns in global order
     * (@p partitioner), so that every process that relaxes a patch sums
     * in the same order.
     */
    void build(const SparseMatrix<double> &                              matrix,
               const std::vector<std::vector<types::global_dof_index>> & patches,
               const std::vector<unsigned int> &                         patch_color,
               const unsigned int                                        n_colors,
               const std::vector<DoFRole> &                              role,
               const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner);

    /**
     * The roles of the linear problem of a Newton step (set up with
     * build() for the constrained problem): a bounded DoF is either fixed
     * (it stays where it is) or free (no bound). Only the patches with a
     * bounded DoF differ from the constrained ones, so only they get a
     * second inverse, of the patch matrix without the fixed DoFs
     * (linear_patch): O(contact patches) work and memory instead of a
     * second set of patches for the whole level.
     */
    void set_linear_roles(const std::vector<DoFRole> &linear_role);

    /** The bytes of the packed arrays, the patch problems and inverses. */
    std::size_t memory_consumption() const;

    /** The number of colors (over all processes). */
    unsigned int n_colors() const
    {
      return color_start.empty() ? 0 : color_start.size() - 1;
    }

    /** The energy check of a patch counts here (see PatchSmoother). */
    std::vector<bool>                      counted;
    std::vector<unsigned int>              start;
    std::vector<std::size_t>               inverse_start;
    std::vector<std::size_t>               neighbor_start;
    AlignedVector<types::global_dof_index> neighbors;
    std::vector<bool>                      bounded;
    AlignedVector<double>                  inverse;
    std::vector<std::size_t>               row_start;
    AlignedVector<std::uint16_t>           columns;
    AlignedVector<double>                  values;
    std::vector<unsigned int>              box_qp;
    std::vector<BoxQP>                     qps;
    std::vector<unsigned int>              color_start;
    /**
     * Linear roles (set_linear_roles()): for a patch with a bounded DoF,
     * linear_patch[box_qp[k]] has the local indices of the DoFs that move
     * and the inverse of their block of the patch matrix (by rows).
     */
    struct LinearPatch
    {
      std::vector<unsigned int> moving;
      std::vector<double>       inverse;
    };
    std::vector<LinearPatch> linear_patch;
  };
} // namespace FoslsContact

#endif
