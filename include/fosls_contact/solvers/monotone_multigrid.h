#ifndef fosls_contact_solvers_monotone_multigrid_h
#define fosls_contact_solvers_monotone_multigrid_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fosls_contact/discretization/level_transfer.h>
#include <fosls_contact/qp/matrix_entry_import.h>
#include <fosls_contact/parameters.h>
#include <fosls_contact/solvers/dense_coarse_solver.h>
#include <fosls_contact/solvers/galerkin_product.h>
#include <fosls_contact/solvers/multilevel_hierarchy.h>
#include <fosls_contact/solvers/patch_smoother.h>
#include <fosls_contact/solvers/qp_solver.h>

#include <chrono>
#include <optional>

namespace FoslsContact
{
  /**
   * The monotone multilevel method of paper sections 4.2, 5 and 6.
   *
   * A cycle on level l minimizes the level functional
   * Q_l(v) = 1/2 v^T A_l v - r_l^T v over v <= ub_l by
   *  1. nu_1 forward sweeps of the patch smoother,
   *  2. gamma times (V: 1, W: 2) a coarse correction: the truncated
   *     prolongation P~ drops the fine DoFs that are fixed or active
   *     (eq. 34), the coarse operator is its Galerkin product
   *     A_{l-1} = P~^T A_l P~, the coarse obstacle is the projection of
   *     the fine defect obstacle (eqs. 31-32, 35-36, CoarseObstacles), and
   *     the coarse problem is solved by one cycle on level l-1,
   *  3. nu_2 backward sweeps;
   * on level 0 the box-constrained problem is solved exactly. (The linear
   * cycle of the Newton step stops earlier, at linear_coarsest, which it
   * solves exactly.)
   *
   * Because A_{l-1} is the Galerkin product, Q_{l-1}(c) = Q_l(v + P~ c) -
   * Q_l(v): every coarse correction minimizes the fine functional itself,
   * so J never increases. This is checked at every sub-step (patch steps
   * and coarse corrections) and reported to the monitor. Should a coarse
   * correction leave the fine feasible set (only possible when the
   * obstacle normals differ between neighbouring vertices), it is shortened
   * to the feasible part, which by convexity along the line still
   * decreases J; the monitor counts these "feasibility dampings".
   *
   * Galerkin operators keep the sparsity of the untruncated product, so a
   * change of the truncation only recomputes values; they are recomputed
   * only when the truncation or the finer operator changed.
   *
   * In the plain cycle, truncated normal stresses are handled by
   * rerouting flux rather than removing the coarse face (reroute_flux()):
   * where the contact zone ends inside a coarse face, the coarse face keeps
   * a basis function that carries its flux through the free sons only.
   * Without it no coarse function can change the total contact force, and
   * the plain cycle stalls (measured on the half disc with 2 levels: rate
   * 0.9999 per cycle, 13 cycles to 1e-8 with it). The linear cycle that
   * preconditions the Newton step removes such faces instead: there the
   * rerouted basis measured worse (half disc, 4 levels: 432 instead of 160
   * cycles; 2 levels: 15 instead of 32).
   *
   * Distributed over the processes of the mesh, the method is the same
   * (same patch order and colors, same truncation, obstacles and coarse
   * problems): vectors are LevelVectors, the level operators local
   * matrices with the owned rows and the ghost rows of the patches
   * (copied from their owners after every Galerkin product), the coarsest
   * problem is gathered on every process and solved there. Numbers differ
   * between process counts only by the order of sums (Galerkin products,
   * dot products).
   */
  template <int dim>
  class MonotoneMultigrid : public QPSolver
  {
  public:
    /**
     * The set-up that depends only on the mesh and on @p fine_sparsity,
     * the pattern of the matrix of the problems to be solved (a
     * ConstrainedQP's compressed pattern): the hierarchy and the patterns
     * of the Galerkin products.
     */
    MonotoneMultigrid(const Discretization<dim> & discretization,
                      const LevelTransfer<dim> &  transfer,
                      const unsigned int          finest_level,
                      const SparsityPattern &     fine_sparsity,
                      const Parameters::Solver &  parameters);

    void solve(const ConstrainedQP &qp,
               LevelVector &        x,
               Monitor &            monitor) override;

    /**
     * The number of patch colors of levels 1..finest (MultilevelHierarchy::
     * patch_colors()): the barriers of the threads and the ghost
     * exchanges of one smoothing step per level.
     */
    std::vector<unsigned int> n_patch_colors() const;

    /**
     * The wall time of the parts of solve() that are called inside the
     * cycles, by name: "Solve: smoothing", "Solve: Galerkin operators and
     * patch setup" (the truncated prolongations, the Galerkin products and
     * the set-up of the patch smoother, of the finest level too) and
     * "Solve: coarse solve".
     *
     * They are timed with a steady clock and not with TimerOutput sections:
     * entering and leaving a TimerOutput section costs about 2 us (a mutex,
     * lookups by string and a system call for the CPU time), and the
     * W-cycle enters about 30 per cycle on level 5 of the square, where
     * that was 8% of the solve time (0.98 s against 0.90 s for 101 solves).
     */
    std::map<std::string, SectionTime> section_times() const override;

    /**
     * The visits of every level by the cycles (those of the coarsest
     * level the cycle reaches are exact solves: level 0, or a finer one in
     * the linear cycle, whose coarser levels then have no visits) and their
     * wall time without that of the coarser levels they visit: where a
     * cycle's time goes. A W-cycle visits level l
     * 2^(finest - l) times per cycle; on a small problem its coarse levels,
     * too small to be split among threads, take a large share of it
     * (bench/level_costs.py, doc/level_costs.md).
     */
    std::vector<SectionTime> level_times() const;

    /**
     * With Solver/Check coarse defects: the number of second visits that
     * took their coarse defect from the first visit's, and the largest
     * difference to the recomputed one (check_coarse_defect()). Both 0
     * without the check.
     */
    std::pair<unsigned int, double> coarse_defect_check() const
    {
      return {n_coarse_defect_checks, coarse_defect_difference};
    }

  private:
    /** Adds the wall time of its lifetime to a SectionTime. */
    class TimedScope
    {
    public:
      explicit TimedScope(SectionTime &time)
        : time(time)
        , start(std::chrono::steady_clock::now())
      {}
      ~TimedScope()
      {
        time.seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++time.calls;
      }

    private:
      SectionTime &                         time;
      std::chrono::steady_clock::time_point start;
    };
    SectionTime smoothing_time, galerkin_time, coarse_time;
    /** The visits of every level by cycle(), with the coarser levels. */
    std::vector<SectionTime> level_time;

    /**
     * The linear cycle (the Newton step's preconditioner) solves the
     * finest level below the finest with at most this many DoFs exactly,
     * by coarse_solve(), in one visit, instead of visiting the levels
     * below it. Its problem is linear (the obstacles of the linear cycle
     * are +inf) and its operator changes only with the roles of a Newton
     * step (the truncation of the linear cycle does not depend on the
     * iterate; on the square it is set up once per solve), so its dense
     * factor is computed that often, and a visit costs two triangular
     * solves with it (since session 13; with the dense inverse before, on
     * the square, level 2 (130 DoFs) took about 34 us per W-cycle visit
     * with the levels below it, 16 us solved exactly). The
     * iterations of the solver tests stayed the same and 9 cycle counts
     * in 5 of them changed (7 down by 1 to 3, 2 up by 1); the time per
     * cycle and DoF went down by 9.6% on level 5 of the square, 4.5% on
     * level 7 and 2.8% on level 9 (by hand: the two binaries alternated,
     * the fastest of 3 runs each, 2 threads). Level 3 (450 DoFs) is too
     * large for it: solved exactly the same way, a level-5 solve took
     * 43 ms instead of 11 (the dense inverse), and UMFPACK took 2.6 ms to
     * factorize it and 0.3 ms per solve (by hand). In 3D level 2 has
     * 1095 DoFs and level 1 189.
     */
    static constexpr unsigned int linear_coarse_max_dofs = 200;
    /** The linear cycle's coarsest level (0 if no level qualifies). */
    unsigned int linear_coarsest = 0;
    /**
     * Whether the cycle (the linear one if @p linear) solves level @p l
     * exactly instead of smoothing it and visiting the levels below.
     */
    bool solved_exactly(const unsigned int l, const bool linear) const
    {
      return l == 0 || (linear && l == linear_coarsest);
    }

    /**
     * One cycle on level @p l for Q_l with matrix @p A; @p v is updated.
     * With @p linear (the Newton step's preconditioner), the finest
     * level is relaxed with the roles of the truncated linear problem
     * (PatchSmoother::set_linear_roles), and coarse faces with a truncated son are removed
     * instead of rerouted. @p type is the cycle on this level (the
     * parameter file's by default; an F-cycle visits its coarser level
     * with an F-cycle and then a V-cycle).
     */
    void cycle(const unsigned int          l,
               const SparseMatrix<double> &A,
               const LevelVector &         r,
               const LevelVector &         ub,
               const std::vector<DoFRole> &role,
               LevelVector &               v,
               const bool                  linear = false,
               std::optional<Parameters::Solver::Cycle> type = {});

    /**
     * The coarse defect of @p v on level @p l, @p r_coarse = P~^T (r - A v),
     * with the fine residual left in @p residual. The ghost values of @p v
     * must be valid. Collective.
     */
    void restrict_defect(const unsigned int          l,
                         const SparseMatrix<double> &A,
                         const LevelVector &         r,
                         const LevelVector &         v,
                         LevelVector &               residual,
                         LevelVector &               r_coarse) const;

    /**
     * The check of Solver/Check coarse defects: @p r_coarse, the coarse
     * defect of @p v on level @p l that the second visit took from the
     * first, against P~^T (r - A v) recomputed. The difference is taken
     * relative to a bound of the terms' size, |P~^T| (|A| |v| + |r|)
     * (max norms), since near the solution r - A v is the small
     * difference of large terms and carries their round-off. Collective.
     */
    void check_coarse_defect(const unsigned int          l,
                             const SparseMatrix<double> &A,
                             const LevelVector &         r,
                             const LevelVector &         v,
                             const LevelVector &         r_coarse);

    /**
     * One step of truncated nonsmooth Newton multigrid with conjugate
     * gradients: projected pre-smoothing, PCG on the inactive set with the
     * linear truncated cycle as preconditioner, projected line search,
     * projected post-smoothing. Returns the number of cycles applied.
     */
    unsigned int newton_step(const ConstrainedQP &qp, LevelVector &x);

    /**
     * Exact solution of the box-constrained problem of level @p l (the
     * coarsest, or the linear cycle's coarsest, linear_coarsest), gathered
     * on every process (the level is small) and solved there alike.
     */
    void coarse_solve(const unsigned int          l,
                      const SparseMatrix<double> &A,
                      const LevelVector &         r,
                      const LevelVector &         ub,
                      const std::vector<DoFRole> &role,
                      LevelVector &               v);

    /**
     * Truncated prolongation and Galerkin operator of level l - 1, rebuilt
     * only when the truncation (or the operator of level l) changed.
     * Returns whether they were rebuilt (the same on every process).
     */
    bool update_coarse_operator(const unsigned int          l,
                                const SparseMatrix<double> &A,
                                const std::vector<DoFRole> &role,
                                const std::vector<bool> &   truncated,
                                const bool                  reroute);

    /**
     * For every coarse contact face of level l - 1 whose sons are partly
     * truncated, give the free sons the flux the truncated ones lost and
     * restore the balance of the fine cells at the sons by a local
     * correction: the change d of the face's column (at its sons) is
     * extended to the free, unbounded DoFs coupled to the sons by A inside
     * the coarse cell (FaceRelation::inside: the column stays inside the
     * cell, so the Galerkin operator stays on the coupling pattern of the
     * coarse cells, which the patch colors rely on),
     * minimizing (d + e)^T A (d + e), so that the column stays nearly
     * divergence free. (A column cut at a son has a divergence of order
     * 1/h in the son's cell: measured 859 vs 0.007 in energy on the half
     * disc.) A face with all sons truncated is removed (@p removed). Sets
     * face_scale[l], the factor the coarse obstacle of each face is
     * divided by (the largest weight of a free son, at least 1).
     */
    void reroute_flux(const unsigned int          l,
                      const SparseMatrix<double> &A,
                      const std::vector<DoFRole> &role,
                      const std::vector<bool> &   truncated,
                      std::vector<types::global_dof_index> &removed,
                      std::vector<std::array<double, 3>> &  entries);

    /**
     * The entries of the level-@p l operator the flux rerouting reads on
     * the faces owned here whose rows other processes own (global indices,
     * sorted): the requests of rerouting_import[l].
     */
    std::vector<MatrixEntryImport::Entry> rerouting_requests(const unsigned int l) const;
    /**
     * Import the entries of rerouting_requests(l) from the operator @p A
     * of level @p l into rerouting_values[l] (collective).
     */
    void import_rerouting_values(const unsigned int l, const SparseMatrix<double> &A);

    /** Work vectors of the cycle on one level (l: fine, l - 1: coarse). */
    struct Scratch
    {
      /** Local fine DoFs (owned and ghost). */
      std::vector<bool> truncated;
      LevelVector       defect, residual, w;
      LevelVector       r_coarse, ub_coarse, c, Ac;
      /** Fixed or switched off (zero diagonal): truncated in every visit. */
      std::vector<bool> fixed_truncated;
      /** The local bounded DoFs that are not fixed_truncated. */
      std::vector<types::global_dof_index> bounded;
      /**
       * The diagonal of the operator (with ghost values), and the operator
       * it belongs to: recomputed when the operator changes, which every
       * process sees at once (the update is collective), while the roles,
       * which decide fixed_truncated too, can change on some processes
       * only.
       */
      LevelVector                           diagonal;
      std::pair<const void *, unsigned int> diagonal_version{nullptr, 0};
      /** The operator and roles fixed_truncated was computed for. */
      std::pair<const void *, unsigned int> operator_version{nullptr, 0};
      std::vector<DoFRole>                  role;
    };

    /** Identifies the operator @p A of level @p l and its current values. */
    std::pair<const void *, unsigned int>
    operator_version(const unsigned int l, const SparseMatrix<double> &A) const
    {
      return {&A, version[l]};
    }

    const MultilevelHierarchy<dim> hierarchy;
    const Parameters::Solver       parameters;
    /** The pattern the Galerkin products were set up for. */
    const SparsityPattern *        fine_sparsity;
    const unsigned int             finest;

    PatchSmoother                                      smoother;
    std::vector<DoFRole>                               linear_role, linear_role_used;
    /** P's pattern plus the DoFs the flux rerouting may use (per level). */
    std::vector<SparsityPattern>                       prolongation_sparsity;
    /** Per coarse contact face owned here (FaceRelation). */
    std::vector<std::vector<double>>                   face_scale;
    /** The Galerkin operators, on the levels' coupling patterns. */
    std::vector<SparseMatrix<double>>                  galerkin;
    std::vector<SparseMatrix<double>>                  truncated_prolongation;
    std::vector<GalerkinProduct>                       galerkin_product;
    /**
     * For the flux rerouting: the entries of the level's operator between
     * the DoFs inside the coarse cells of the contact faces owned here
     * whose rows other processes own (their requests, and the values of
     * the last operator).
     */
    std::vector<MatrixEntryImport>                     rerouting_import;
    /** (local row, local column) of the requests of each level */
    std::vector<std::vector<std::pair<types::global_dof_index, types::global_dof_index>>>
                                                       rerouting_entries;
    std::vector<std::map<std::pair<types::global_dof_index, types::global_dof_index>, double>>
                                                       rerouting_values;
    std::vector<Scratch>                               scratch;
    std::vector<std::vector<bool>>                     truncation_used;
    std::vector<unsigned int>                          version, version_used;
    std::vector<bool>                                  reroute_used;
    /**
     * The coarsest problem in global numbering (coarse_global: the level's
     * own matrix on one process, else coarse_matrix_global, gathered on
     * every process), and the exact solver of its dense matrix on the DoFs
     * that move (coarse_dofs, up to 2000 of them).
     */
    DenseCoarseSolver                                  coarse_dense_solver;
    std::vector<types::global_dof_index>               coarse_dofs;
    SparsityPattern                                    coarse_sparsity_global;
    SparseMatrix<double>                               coarse_matrix_global;
    const SparseMatrix<double> *                       coarse_global = nullptr;
    std::vector<DoFRole>                               coarse_role_global;
    /** The work arrays of the coarse solve (whole coarsest vectors). */
    struct CoarseWork
    {
      Vector<double>      r_all, ub_all, v_all, g, s, c, Av;
      std::vector<double> owned_triples, all_triples;
      std::vector<bool>   at_bound;
    } coarse_work;
    /**
     * Per process: three times its number of owned coarsest DoFs (r, ub
     * and v of each), and their offsets.
     */
    std::vector<int>                                   coarse_counts, coarse_displacements;
    const SparseMatrix<double> *                       coarse_matrix  = nullptr;
    unsigned int                                       coarse_version = numbers::invalid_unsigned_int;
    unsigned int                                       n_increases = 0;
    unsigned int                                       n_dampings  = 0;
    unsigned int                                       n_coarse_defect_checks   = 0;
    double                                             coarse_defect_difference = 0;
  };
} // namespace FoslsContact

#endif
