#ifndef fosls_contact_solvers_patch_smoother_h
#define fosls_contact_solvers_patch_smoother_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/multigrid/mg_smoother.h>

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/solvers/box_qp.h>

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
   */
  class PatchSmoother : public MGSmoother<Vector<double>>
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
                          const std::vector<DoFRole> &                            role);

    /** Obstacles of level @p l: the upper bounds of bounded DoFs. */
    void set_obstacles(const unsigned int l, const Vector<double> &upper_bounds);
    /** Forward (pre-smoothing) or backward (post-smoothing) patch order. */
    void set_backward(const bool backward) { this->backward = backward; }

    void smooth(const unsigned int    level,
                Vector<double> &      v,
                const Vector<double> &r) const override;
    void clear() override;

    /** Patch steps whose objective change was positive beyond round-off. */
    unsigned int energy_increases() const { return n_increases; }

  private:
    /**
     * The patches of one level, packed: patch k has the DoFs
     * dofs[start[k] .. start[k+1]) and the inverse of its matrix (row
     * major) at inverse[inverse_start[k] ..). A sweep streams through
     * these arrays in order, which matters once a level no longer fits in
     * cache (the inverses are as large as the sparse matrix). Only patches
     * with a bounded DoF can hit an obstacle, so only they keep a BoxQP
     * for the constrained case (box_qp[k], an index into qps).
     *
     * The matrix rows of the patch DoFs are copied next to each other as
     * well (row_start, columns, values; a row of a face DoF appears in the
     * two patches of the face's end points): the patch residual then reads
     * one contiguous block instead of jumping through the sparse matrix,
     * which is what a sweep spends most of its time on.
     */
    struct Level
    {
      const Vector<double> *               obstacles = nullptr;
      std::vector<unsigned int>            start;
      std::vector<std::size_t>             inverse_start;
      std::vector<types::global_dof_index> dofs;
      std::vector<bool>                    bounded;
      std::vector<double>                  inverse;
      std::vector<std::size_t>             row_start;
      std::vector<unsigned int>            columns;
      std::vector<double>                  values;
      std::vector<unsigned int>            box_qp;
      std::vector<BoxQP>                   qps;
    };
    std::vector<Level>   levels;
    bool                 backward    = false;
    mutable unsigned int n_increases = 0;
  };
} // namespace FoslsContact

#endif
