#ifndef fosls_contact_solvers_packed_patches_h
#define fosls_contact_solvers_packed_patches_h

#include <deal.II/base/aligned_vector.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparse_matrix.h>

#include <fosls_contact/qp/dof_role.h>
#include <fosls_contact/solvers/box_qp.h>
#include <fosls_contact/solvers/pair_terms.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace FoslsContact
{
  /**
   * The vertex patches of one level, packed for the sweeps of the
   * PatchSmoother: their DoFs, a copy of their matrix rows and the inverse
   * of every patch matrix, in sweep order, color by color. A sweep streams
   * through these arrays in order, and on the largest levels they no
   * longer fit in cache (about twice the matrix; doc/performance.md,
   * section 1), so their size is the time of a sweep there:
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
   * - only patches with a bounded DoF can hit an obstacle (or, with
   *   friction, a DoF of role traction or slip its bound or kink), so only
   *   they keep a BoxQP for the constrained case (box_qp[k], an index into
   *   qps); roles has the role of every patch DoF.
   *
   * Without copied rows (build() with copy_rows false) a patch's
   * neighbourhood is just its DoFs, and row_start, columns and values are
   * empty: the sweeps read the rows of the level matrix (matrix), with
   * the same terms in the same order (row_defect()), so the iterates are
   * the same to the bit. In 3D a face DoF's row is in the patches of the
   * face's four vertices: 1,800 of the 2,270 bytes per DoF of the cube's
   * patches at level 7 are the copied rows. The price is the sweep's
   * time: the rows of a patch lie wherever the matrix has them, not one
   * after the other in sweep order (doc/performance.md).
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
     * in the same order. With @p copy_rows false the rows stay in
     * @p matrix, which must then outlive the patches unchanged.
     */
    void build(const SparseMatrix<double> &                              matrix,
               const std::vector<std::vector<types::global_dof_index>> & patches,
               const std::vector<unsigned int> &                         patch_color,
               const unsigned int                                        n_colors,
               const std::vector<DoFRole> &                              role,
               const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
               const bool                                                copy_rows = true);

    /**
     * g_i minus the product of row @p i of #matrix (rows not copied) with
     * @p v: the terms in the global order of their columns, as a copied
     * row has them, so that the result is the same to the bit. A row of
     * the matrix is the diagonal and then the other local columns in
     * increasing order: the owned DoFs (contiguous and increasing in
     * global order too), the ghosts below the owned range and the ghosts
     * above it. Zero entries, which a copied row leaves out, subtract
     * exact zeros.
     */
    double row_defect(const unsigned int i, const double *v, double g_i) const;

    /**
     * The roles of the linear problem of a Newton step (set up with
     * build() for the constrained problem): a bounded DoF is either fixed
     * (it stays where it is) or free (no bound). Only the patches with a
     * bounded DoF differ from the constrained ones, so only they get a
     * second inverse, of the patch matrix without the fixed DoFs
     * (linear_patch): O(contact patches) work and memory instead of a
     * second set of patches for the whole level. With @p pair_terms the
     * patch matrices and defects of the linear problem include K.
     */
    void set_linear_roles(const std::vector<DoFRole> &linear_role,
                          const PairTerms *           pair_terms = nullptr);

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
    std::vector<DoFRole>                   roles;
    AlignedVector<double>                  inverse;
    std::vector<std::size_t>               row_start;
    AlignedVector<std::uint16_t>           columns;
    AlignedVector<double>                  values;
    std::vector<unsigned int>              box_qp;
    /** Whether patch k has a DoF of role traction or slip. */
    std::vector<bool>                      friction;
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
      /**
       * The pair terms K (PairTerms) at the moving DoFs: g_a -= K_ii v_i +
       * K_ij v_j for the DoF i at patch position a with partner j.
       */
      struct PairEntry
      {
        unsigned int a, i, j;
        double       k_ii, k_ij;
      };
      std::vector<PairEntry> pair_entries;
    };
    std::vector<LinearPatch> linear_patch;
    /**
     * The level matrix whose rows the sweeps read (nullptr if copied), and
     * its values by the pattern's linear index: the address of entry
     * (0, 0), the first one a square SparseMatrix stores.
     */
    const SparseMatrix<double> *matrix        = nullptr;
    const double *              matrix_values = nullptr;
    /**
     * The owned DoFs are the local ones below n_owned, the ghosts below
     * the owned range in global order those from n_owned to ghosts_above.
     */
    unsigned int n_owned = 0, ghosts_above = 0;
  };


  inline double
  PackedPatches::row_defect(const unsigned int i, const double *v, double g_i) const
  {
    const SparsityPattern &pattern = matrix->get_sparsity_pattern();
    const unsigned int     length  = pattern.row_length(i);
    const double *         value   = matrix_values + pattern.begin(i)->global_index();
    const auto column = [&](const unsigned int j) { return pattern.column_number(i, j); };
    unsigned int above = length; // the first ghost above the owned range
    while (above > 1 && column(above - 1) >= ghosts_above)
      --above;
    unsigned int ghosts = above; // the first ghost
    while (ghosts > 1 && column(ghosts - 1) >= n_owned)
      --ghosts;
    const double diagonal_term = value[0] * v[i];
    // the terms of entries [j, end) in order, the diagonal's at its column
    // if @p holds_diagonal
    const auto subtract = [&](unsigned int j, const unsigned int end, const bool holds_diagonal) {
      if (holds_diagonal)
        {
          for (; j < end && column(j) < i; ++j)
            g_i -= value[j] * v[column(j)];
          g_i -= diagonal_term;
        }
      for (; j < end; ++j)
        g_i -= value[j] * v[column(j)];
    };
    subtract(ghosts, above, n_owned <= i && i < ghosts_above);
    subtract(1, ghosts, i < n_owned);
    subtract(above, length, ghosts_above <= i);
    return g_i;
  }
} // namespace FoslsContact

#endif
