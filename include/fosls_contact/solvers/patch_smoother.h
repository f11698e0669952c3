#ifndef fosls_contact_solvers_patch_smoother_h
#define fosls_contact_solvers_patch_smoother_h

#include <deal.II/base/aligned_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/solvers/box_qp.h>

#include <atomic>
#include <cstdint>

namespace FoslsContact
{
  /**
   * Projected relaxation over Arnold-Falk-Winther vertex patches, as an
   * MGSmoother: smooth(level, v, r) minimizes 1/2 v^T A v - r^T v, patch
   * after patch, exactly within the obstacles v <= ub set with
   * set_obstacles() (paper eqs. 19-24). The patch spans the vertex's
   * displacement and the fluxes (all stress rows) of the faces at the
   * vertex, which is what makes relaxation effective for the large
   * divergence-free part of H(div) (Arnold, Falk, Winther).
   *
   * The patch matrices and their inverses are set up once per level
   * matrix (initialize_level), which happens only when a Galerkin operator
   * changes, i.e. when the truncation changes.
   *
   * The sweep is the sequential one in the order of the hierarchy's
   * patches (MultilevelHierarchy::patches(): backward for post-smoothing),
   * run in parallel without changing a bit of it: the patches come with
   * colors (MultilevelHierarchy::patch_colors(), the level scheduling of
   * that order), two patches the matrix couples keep their order, and the
   * patches of one color, which are independent, are relaxed concurrently
   * by the threads of MultithreadInfo. The iterates are therefore the
   * same for any number of threads, and the same as those of the serial
   * sweep. initialize_level() refuses a matrix that couples two patches of
   * one color. (A greedy coloring with the fewest colors, i.e. a
   * multicolor Gauss-Seidel order, was measured too: plain V(3,3) on the
   * square, lambda = 1, asymptotic rate 0.67-0.71 instead of 0.27-0.35.)
   *
   * Distributed: a process relaxes every patch with a DoF it owns, so a
   * patch at the border of its cells is relaxed by each process that owns
   * one of its DoFs, from the same values (the ghost values are updated
   * after every color), with the same rows (ghost rows are copies of their
   * owners') in the same order (global order of the DoFs and columns): to
   * the same bits. Each process thus has the new values of its own DoFs,
   * and the sweep is the sequential one for any number of processes too.
   * An energy increase of a patch is counted by the owner of its first
   * moving DoF only.
   */
  class PatchSmoother : public MGSmoother<LevelVector>
  {
  public:
    explicit PatchSmoother(const unsigned int n_levels);

    /**
     * Factorize the patches of level @p l for @p matrix (whose rows are
     * copied: a changed matrix needs a new call). Fixed DoFs and DoFs with
     * a zero diagonal (switched off by the truncation of the finer level)
     * are left out of every patch.
     */
    void initialize_level(const unsigned int                                      l,
                          const SparseMatrix<double> &                            matrix,
                          const std::vector<std::vector<types::global_dof_index>> &patches,
                          const std::vector<unsigned int> &                       colors,
                          const unsigned int                                      n_colors,
                          const std::vector<DoFRole> &                            role,
                          const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner);

    /**
     * The roles of the linear problem of a Newton step on level @p l (set
     * up with initialize_level for the constrained problem): a bounded DoF
     * is either fixed (it stays where it is) or free (no bound). Only the
     * patches with a bounded DoF differ from the constrained smoother, so
     * only they get a second inverse, of the patch matrix without the
     * fixed DoFs: O(contact patches) work and memory instead of a second
     * smoother of the whole level.
     */
    void set_linear_roles(const unsigned int l, const std::vector<DoFRole> &linear_role);
    /**
     * Relax level @p l with the linear roles (true) or with the obstacles
     * of set_obstacles() (false).
     */
    void use_linear_roles(const unsigned int l, const bool linear)
    {
      levels[l].linear = linear;
    }

    /** Obstacles of level @p l: the upper bounds of bounded DoFs. */
    void set_obstacles(const unsigned int l, const LevelVector &upper_bounds);
    /** Forward (pre-smoothing) or backward (post-smoothing) patch order. */
    void set_backward(const bool backward) { this->backward = backward; }

    /**
     * The sweeps on level @p level: @p v changes on the owned DoFs and the
     * ghost DoFs of the patches relaxed here; its ghost values are valid
     * afterwards. Collective.
     */
    void smooth(const unsigned int level,
                LevelVector &      v,
                const LevelVector &r) const override;
    void clear() override;

    /** Patch steps whose objective change was positive beyond round-off. */
    unsigned int energy_increases() const { return n_increases; }

    /** Number of colors of level @p l, over all processes. */
    unsigned int n_colors(const unsigned int l) const
    {
      return levels[l].color_start.empty() ? 0 : levels[l].color_start.size() - 1;
    }

  private:
    /**
     * The patches of one level, packed. A sweep streams through these
     * arrays in order, and from level 8 of the square on they no longer
     * fit in cache (240 MB at level 9, against 110 MB for the matrix), so
     * their size is the time of a sweep there:
     * - patch k has n = start[k+1] - start[k] DoFs; its neighbourhood, the
     *   columns of its rows, is neighbors[neighbor_start[k] ..
     *   neighbor_start[k+1]), the patch DoFs first;
     * - its rows are copied next to each other (row_start, columns,
     *   values; a row of a face DoF appears in the two patches of the
     *   face's end points), so that the patch residual reads one
     *   contiguous block instead of jumping through the sparse matrix. The
     *   columns are 16-bit positions in the neighbourhood, whose values a
     *   relaxation gathers first (against 32-bit DoF indices: 15% less
     *   data);
     * - the inverse of its matrix is stored as its upper triangle by rows
     *   at inverse[inverse_start[k] ..) (n (n+1)/2 entries instead of n^2);
     * - only patches with a bounded DoF can hit an obstacle, so only they
     *   keep a BoxQP for the constrained case (box_qp[k], an index into
     *   qps).
     *
     * The patches are packed color by color: those of color k are
     * color_start[k] .. color_start[k+1]. The large arrays are
     * AlignedVectors, whose resize_fast() leaves new entries uninitialized
     * for the parallel fill of initialize_level().
     */
    struct Level
    {
      const LevelVector *                  obstacles = nullptr;
      /** The patch's energy check counts here (see the class doc). */
      std::vector<bool>                    counted;
      std::vector<unsigned int>            start;
      std::vector<std::size_t>             inverse_start;
      std::vector<std::size_t>             neighbor_start;
      AlignedVector<types::global_dof_index> neighbors;
      std::vector<bool>                    bounded;
      AlignedVector<double>                inverse;
      std::vector<std::size_t>             row_start;
      AlignedVector<std::uint16_t>         columns;
      AlignedVector<double>                values;
      std::vector<unsigned int>            box_qp;
      std::vector<BoxQP>                   qps;
      std::vector<unsigned int>            color_start;
      /**
       * Linear roles (set_linear_roles): for a patch with a bounded DoF,
       * linear_patch[box_qp[k]] has the local indices of the DoFs that
       * move and the inverse of their block of the patch matrix.
       */
      struct LinearPatch
      {
        std::vector<unsigned int> moving;
        std::vector<double>       inverse;
      };
      std::vector<LinearPatch> linear_patch;
      bool                     linear = false;
    };

    /**
     * Relax the packed patches [begin, end) of @p level once (they are of
     * one color, so their order does not matter).
     */
    void relax_patches(const Level &      level,
                       const unsigned int begin,
                       const unsigned int end,
                       LevelVector &      v,
                       const LevelVector &r) const;

    std::vector<Level>                levels;
    bool                              backward    = false;
    mutable std::atomic<unsigned int> n_increases = 0;
  };
} // namespace FoslsContact

#endif
