#ifndef fosls_contact_solvers_patch_smoother_h
#define fosls_contact_solvers_patch_smoother_h

#include <deal.II/multigrid/mg_smoother.h>

#include <fosls_contact/parameters/solver.h>
#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/qp/matrix_list_memory.h>
#include <fosls_contact/solvers/packed_patches.h>
#include <fosls_contact/solvers/solver_statistics.h>

#include <atomic>
#include <memory>
#include <vector>

namespace FoslsContact
{
  struct FrictionTerms;

  /**
   * Projected relaxation over Arnold-Falk-Winther vertex patches, as an
   * MGSmoother: smooth(level, v, r) minimizes 1/2 v^T A v - r^T v, patch
   * after patch, exactly within the obstacles v <= ub set with
   * set_obstacles() (paper eqs. 19-24), MGSmoother::steps times, forward
   * in the patch order or, with MGSmoother::transpose, backward (the
   * transpose of a Gauss-Seidel sweep; with MGSmoother::symmetric the
   * direction alternates). The patch spans the vertex's displacement and
   * the fluxes (all stress rows) of the faces at the vertex, which is what
   * makes relaxation effective for the large divergence-free part of
   * H(div) (Arnold, Falk, Winther).
   *
   * The patches of every level are packed (PackedPatches) once per level
   * matrix (initialize_level()), which happens only when a Galerkin
   * operator changes, i.e. when the truncation changes. A pre- and a
   * post-smoother share them: PatchSmoother(other, steps, transpose)
   * makes a smoother on the patches of another, with its own steps and
   * direction.
   *
   * The sweep is the sequential one in the order of the hierarchy's
   * patches (MultilevelHierarchy::patches()), run in parallel without
   * changing a bit of it: the patches come with colors
   * (MultilevelHierarchy::patch_colors(), the level scheduling of that
   * order), two patches the matrix couples keep their order, and the
   * patches of one color, which are independent, are relaxed concurrently
   * by the threads of MultithreadInfo. The iterates are therefore the same
   * for any number of threads, and the same as those of the serial sweep.
   * (A greedy coloring with the fewest colors, i.e. a multicolor
   * Gauss-Seidel order, smooths far worse: doc/performance.md, "Figures behind the code".)
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
    using PatchRows = Parameters::Solver::PatchRows;

    /**
     * A smoother for levels 0 .. @p n_levels - 1 (no patches yet) with
     * @p steps sweeps, backward if @p transpose; the wall time of its
     * sweeps is added to @p time if given. Its patches copy their matrix
     * rows or read those of the level matrices (@p rows).
     */
    PatchSmoother(const unsigned int n_levels,
                  const unsigned int steps     = 1,
                  const bool         transpose = false,
                  SectionTime *      time      = nullptr,
                  const PatchRows    rows      = PatchRows::copied);
    /**
     * A smoother on the patches, obstacles and roles of @p other (what is
     * set on one, the other sees), with its own @p steps and direction.
     */
    PatchSmoother(const PatchSmoother &other, const unsigned int steps, const bool transpose);

    /**
     * Pack the patches of level @p l for @p matrix (PackedPatches::build()).
     * The level relaxes with the obstacles of the next set_obstacles() and
     * the roles @p role. Where the rows are read from @p matrix it must
     * stay as it is until the next call for the level (the multigrid
     * cycles call it after every change of the Galerkin operator of a
     * level they smooth; LevelOperators::needs_update() rebuilds an
     * operator whose truncation or rerouting changed since).
     */
    void initialize_level(const unsigned int                                      l,
                          const SparseMatrix<double> &                            matrix,
                          const std::vector<std::vector<types::global_dof_index>> &patches,
                          const std::vector<unsigned int> &                       colors,
                          const unsigned int                                      n_colors,
                          const std::vector<DoFRole> &                            role,
                          const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner);

    /**
     * The roles of the linear problem of a Newton step on level @p l
     * with the pair terms K it adds to A, if any
     * (PackedPatches::set_linear_roles()).
     */
    void set_linear_roles(const unsigned int          l,
                          const std::vector<DoFRole> &linear_role,
                          const PairTerms *           pair_terms = nullptr);
    /**
     * Relax level @p l with the linear roles (true) or with the obstacles
     * of set_obstacles() (false).
     */
    void use_linear_roles(const unsigned int l, const bool linear);

    /** Obstacles of level @p l: the upper bounds of bounded DoFs. */
    void set_obstacles(const unsigned int l, const LevelVector &upper_bounds);

    /**
     * The friction terms of J on level @p l (nullptr: none; the DoFs of
     * roles traction and slip are then free, as on the coarse levels,
     * whose problems are the Newton step's linear ones, in which a fine
     * friction DoF is held or free). With them a patch with such a DoF is
     * relaxed exactly with its bounds and kinks
     * (BoxQP::solve_with_friction()), and a patch with 3D pairs by block
     * coordinate descent over its scalar entries and its pairs
     * (TangentialPair). They must outlive the smoothing.
     */
    void set_friction(const unsigned int l, const FrictionTerms *friction);

    /**
     * The sweeps on level @p level: @p v changes on the owned DoFs and the
     * ghost DoFs of the patches relaxed here; its ghost values are valid
     * afterwards. Collective.
     */
    void smooth(const unsigned int level, LevelVector &v, const LevelVector &r) const override;
    void clear() override;

    /** Patch steps whose objective change was positive beyond round-off. */
    unsigned int energy_increases() const { return shared->n_increases; }
    /**
     * The sweeps over every level so far, by this smoother and those that
     * share its patches: with the levels' DoFs the work of a solve in
     * work units (SolverStatistics::Multilevel::level_sweeps).
     */
    const std::vector<unsigned long long> &sweeps() const { return shared->sweeps; }

    /** The bytes of the packed patches by level (shared by the copies). */
    LevelBytes memory_consumption() const;

    /** Number of colors of level @p l, over all processes. */
    unsigned int n_colors(const unsigned int l) const
    {
      return shared->levels[l].n_colors();
    }

  private:
    /** What the smoothers on the same patches share. */
    struct Shared
    {
      Shared(const unsigned int n_levels, const PatchRows rows)
        : rows(rows)
        , levels(n_levels)
        , obstacles(n_levels, nullptr)
        , friction(n_levels, nullptr)
        , linear(n_levels, false)
        , sweeps(n_levels, 0)
      {}
      const PatchRows                   rows;
      std::vector<PackedPatches>        levels;
      std::vector<const LevelVector *>  obstacles;
      std::vector<const FrictionTerms *> friction;
      std::vector<bool>                 linear;
      std::atomic<unsigned int>         n_increases{0};
      /** The sweeps of every level, by all smoothers on these patches. */
      std::vector<unsigned long long> sweeps;
    };

    /** One sweep over the colors of level @p l, backward if @p backward. */
    void sweep(const unsigned int l, LevelVector &v, const LevelVector &r, const bool backward) const;
    /**
     * Relax the packed patches [begin, end) of level @p l once (they are
     * of one color, so their order does not matter).
     */
    void relax_patches(const unsigned int l,
                       const unsigned int begin,
                       const unsigned int end,
                       LevelVector &      v,
                       const LevelVector &r) const;

    std::shared_ptr<Shared> shared;
    SectionTime *           time;
  };
} // namespace FoslsContact

#endif
