#ifndef fosls_contact_solvers_coarse_solver_h
#define fosls_contact_solvers_coarse_solver_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/qp/dof_role.h>
#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/qp/sparse_direct_solver.h>
#include <fosls_contact/solvers/dense_coarse_solver.h>
#include <fosls_contact/solvers/solver_statistics.h>

#include <vector>

namespace FoslsContact
{
  /**
   * The exact solution of the box-constrained problem of the coarsest
   * level a cycle visits (level 0, or the linear cycle's coarsest level):
   * minimize 1/2 v^T A v - r^T v subject to v_i <= ub_i (bounded DoFs),
   * v_i fixed (fixed DoFs and DoFs with a zero diagonal, switched off by
   * the truncation of the finer level).
   *
   * The level is small: its operator is gathered on every process (on
   * several processes; on one the level's own matrix is used) and the
   * problem solved there alike, with the dense matrix of the DoFs that
   * move (DenseCoarseSolver: a Cholesky factor for a visit without finite
   * bounds, a BoxQP otherwise), or with the sparse active set method above
   * max_dense_dofs of them. The set-up is done once per operator (it
   * changes only with the truncation, while the W-cycles of a Newton step
   * visit the level hundreds of times). The sparse path keeps the factor
   * of its last active set for the same reason (solve_held()).
   */
  class CoarseSolver
  {
  public:
    /** The wall time of the solves is added to @p time if given. */
    explicit CoarseSolver(SectionTime *time = nullptr)
      : time(time)
    {}

    /**
     * Solve the problem of the level with @p partitioner (every process
     * takes part, also one without DoFs of it) for the operator @p A in
     * the version @p version of its values (a new version means a new
     * set-up), from @p v: all local entries of @p v (owned and ghost) are
     * the solution afterwards. Collective.
     */
    void solve(const Utilities::MPI::Partitioner &partitioner,
               const SparseMatrix<double> &       A,
               const unsigned int                 version,
               const LevelVector &                r,
               const LevelVector &                ub,
               const std::vector<DoFRole> &       role,
               LevelVector &                      v);

    /**
     * The sparse factorizations made for the kept factor so far (the
     * active set method's own are not counted): one per operator where
     * every visit keeps the active set.
     */
    unsigned int kept_factorizations() const { return n_kept_factorizations; }

  private:
    /**
     * Above this many DoFs that move the coarse problem is solved by the
     * sparse active set method instead of the dense matrix: its dense
     * inverse (n^2 doubles, n^3 to make) would cost more than the solves
     * (the half disc's level 0 has 434 DoFs, the 3D Cattaneo-Mindlin
     * scene's 3,903).
     */
    static constexpr unsigned int max_dense_dofs = 2000;
    /** The step limit of the sparse active set method there. */
    static constexpr unsigned int max_sparse_steps = 100;

    /** The gathered operator and roles and the dense solver of @p A. */
    void set_up(const Utilities::MPI::Partitioner &partitioner,
                const SparseMatrix<double> &       A,
                const std::vector<DoFRole> &       role);
    /** r, ub and v of all processes into r_all, ub_all, v_all. Collective. */
    void gather(const Utilities::MPI::Partitioner &partitioner,
                const LevelVector &                r,
                const LevelVector &                ub,
                const LevelVector &                v);
    /** The dense solve of the gathered problem, into v_all. */
    void solve_dense();
    /** The sparse solve of the gathered problem, into v_all. */
    void solve_sparse();
    /**
     * The sparse path's shortcut: the minimizer with the DoFs of held
     * eliminated (held at their bound, or fixed at v) by the kept factor,
     * into v_all if it is the solution, i.e. if the active set method
     * would stop there (a held bound's multiplier is > 0, a free bounded
     * DoF lies at or below its bound); false, and v_all unchanged,
     * otherwise. The result is the active set method's bit for bit when
     * its last step has the same set: the same eliminated system, solved
     * the same way. Every visit of the Newton step's linear cycle (no
     * finite bound) is then one back substitution instead of one
     * factorization: with a factorization per visit the coarse solves of
     * the 3D Cattaneo-Mindlin scene (3,903 coarse DoFs) took 125 of the
     * 160 s of its pressed step, with the kept factor 9.5 s
     * (doc/performance.md).
     */
    bool solve_held();
    /**
     * held: the fixed DoFs, those with a zero diagonal and the bounded ones
     * v_all is at (or beyond) the bound of; and the factor of the gathered
     * matrix with them eliminated (identity rows and columns), for
     * solve_held().
     */
    void hold_where_at_bound();

    SectionTime *time;
    /** The operator and version the set-up is for. */
    const SparseMatrix<double> *matrix  = nullptr;
    unsigned int                version = numbers::invalid_unsigned_int;
    /**
     * The problem in global numbering (global: the level's own matrix on
     * one process, else matrix_global, gathered on every process), and the
     * exact solver of its dense matrix on the DoFs that move (dofs).
     */
    DenseCoarseSolver                    dense_solver;
    std::vector<types::global_dof_index> dofs;
    /**
     * The sparse path's kept factor (empty after a set-up) and the DoFs it
     * eliminates: the fixed ones, those with a zero diagonal, and the
     * bounded ones held at their bound by the last active set.
     */
    std::unique_ptr<SparseDirectSolver> held_factor;
    std::vector<bool>                   held;
    unsigned int                        n_kept_factorizations = 0;
    SparsityPattern                      sparsity_global;
    SparseMatrix<double>                 matrix_global;
    const SparseMatrix<double> *         global = nullptr;
    std::vector<DoFRole>                 role_global;
    /**
     * Per process: three times its number of owned DoFs (r, ub and v of
     * each), and their offsets.
     */
    std::vector<int> counts, displacements;
    /**
     * The work arrays of a solve, kept: a W-cycle visits the coarse level
     * hundreds of times per Newton step, and allocating them per call
     * made a coarse solve a sixth slower.
     */
    Vector<double>      r_all, ub_all, v_all, g, s, c, Av;
    std::vector<double> owned_triples, all_triples;
    std::vector<bool>   at_bound;
  };
} // namespace FoslsContact

#endif
