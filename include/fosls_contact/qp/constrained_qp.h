#ifndef fosls_contact_qp_constrained_qp_h
#define fosls_contact_qp_constrained_qp_h

#include <deal.II/lac/sparse_matrix.h>

#include <fosls_contact/qp/algebraic_level.h>
#include <fosls_contact/qp/dof_role.h>
#include <fosls_contact/qp/level_algebra.h>
#include <fosls_contact/qp/sparse_round_off.h>

#include <functional>

namespace FoslsContact
{
  /** Residuals of the KKT conditions of a ConstrainedQP, relative to |b|. */
  struct KKTResidual
  {
    double stationarity    = 0; ///< max |(A x - b)_i + mu_i| over non-fixed i
    double feasibility     = 0; ///< max (x_i - ub_i)_+ and |x_i - fixed_i|
    double complementarity = 0; ///< max |mu_i (ub_i - x_i)|
    double max() const
    {
      return std::max(stationarity, std::max(feasibility, complementarity));
    }
  };

  /** The three parts of the functional J of eqs. (1)-(2). */
  struct FunctionalValue
  {
    double total = 0, eq = 0, constitutive = 0, complementarity = 0;
  };

  /** What a solver's monitor records of an iterate (ConstrainedQP::measure()). */
  struct IterateMeasures
  {
    FunctionalValue functional;     ///< ConstrainedQP::parts() at the iterate
    double          correction = 0; ///< ConstrainedQP::energy_norm() of the correction
    double          round_off  = 0; ///< ConstrainedQP::round_off_correction() at the iterate
    /**
     * The round-off of J at the iterate: machine epsilon times the sum of
     * the magnitudes of its terms (|x|^T |A| |x| / 2 + |b|^T |x| + |c|).
     * J is summed accurately, but the matrix's entries carry the round-off
     * of their assembly, which is of this size in J; where it reaches J
     * itself (weights or cell sizes many orders apart), a step of the
     * solver can raise J by round-off alone.
     */
    double functional_round_off = 0;
  };

  /**
   * The friction terms of J (Friction/Law, doc/method.md section 7.7): a
   * DoF of role traction (a tangential contact traction) is bounded by
   * |x_i| <= traction_bounds_i (the slip bound s of its face), and a DoF
   * of role slip (a tangential displacement of a contact vertex) adds
   * slip_weights_i |x_i - slip_references_i| to J: C_compl s |u_t - p_t|
   * by the trapezoidal rule, with p the displacement the step starts
   * from. The vectors are empty without friction.
   *
   * In 3D the two tangential coordinates of a face or a vertex are a
   * pair (@p partner): the bound is the disc |(x_i, x_j)| <= s and the
   * term w |(x_i - p_i, x_j - p_j)| (the Euclidean norm: isotropic
   * friction), with the same s or w on both entries.
   */
  struct FrictionTerms
  {
    LevelVector traction_bounds, slip_weights, slip_references;
    /**
     * The local index of the other tangential coordinate of the same face
     * or vertex (owned and ghost DoFs: both coordinates of one face or
     * vertex have one owner), or no_partner: an entry alone (2D, where
     * the vector is empty, and a vertex of a roller whose other
     * tangential coordinate is prescribed).
     */
    std::vector<unsigned int> partner;

    static constexpr unsigned int no_partner = static_cast<unsigned int>(-1);
    /** partner[i], or no_partner. */
    unsigned int partner_of(const unsigned int i) const
    {
      return partner.empty() ? no_partner : partner[i];
    }
    /** Whether any entry has a partner (collective: the same on every process). */
    bool has_pairs() const { return !partner.empty(); }
  };

  /**
   * The seam of the program: a box-constrained quadratic problem
   *
   *   minimize J(x) = 1/2 x^T A x - b^T x + c
   *   subject to x_i = fixed_i (role fixed), x_i <= ub_i (role bounded),
   *
   * and, with friction (FrictionTerms), |x_i| <= s_i (role traction) and
   * the term sum_i w_i |x_i - p_i| in J (role slip),
   *
   * in the normal-tangential basis (paper section 4.3), so that every
   * contact constraint bounds one DoF. J is the least-squares functional
   * itself (A is twice the Gram matrix), so J(x) is the a posteriori error
   * estimate of the paper. The solvers see only this object.
   *
   * The matrices of the equilibrium and complementarity parts are kept as
   * well, only to report J's parts; the constitutive part is the rest.
   *
   * Distributed over the processes of the level (LevelVector): the
   * vectors and the roles in local indices, the matrices as local matrices
   * with the owned rows (and, for A, the ghost rows of the vertex patches,
   * AlgebraicLevel::sparsity). Every function that returns a number (J, norms,
   * counts, residuals) returns the value over all processes.
   */
  struct ConstrainedQP
  {
    /**
     * A, after compress_matrices() on the pattern of its own nonzero
     * entries (@p sparsity) rather than on the DoF coupling pattern of the
     * level: at level 9 of the square that pattern holds 27% entries that
     * are zero or round-off (|a_ij| <= 1e-15 sqrt(a_ii a_jj), where an
     * exact computation gives 0; the smallest genuine entry is 1e-8 of
     * that), and every product with A, every Galerkin product and every
     * patch residual would stream them.
     */
    SparseMatrix<double> matrix;
    SparsityPattern      sparsity;
    /**
     * The DoF coupling pattern of the level (AlgebraicLevel::sparsity, set
     * by reinit()), which holds A's pattern: the direct solver factorizes
     * on it (see SparseDirectSolver::initialize()). Null once the pattern
     * is freed for a multigrid solve (Discretization::release_coupling_pattern()).
     */
    const SparsityPattern *coupling_sparsity = nullptr;
    /** The level's partitioner: owned and ghost DoFs. */
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
    /** Copies the ghost rows of A (on coupling_sparsity) from their owners. */
    const MatrixEntryImport *ghost_rows = nullptr;
    LevelVector              rhs;
    /** The constant of J (over all processes). */
    double                   constant = 0;

    /**
     * After compress_matrices(), on patterns of their own nonzero
     * entries: the equilibrium part couples only fluxes of one stress row
     * in one cell, the complementarity part only contact DoFs, so they are
     * a fraction of A (at level 9 of the square 15% and 0.1% of its
     * entries) instead of two more copies of it.
     */
    SparseMatrix<double> matrix_eq, matrix_compl;
    SparsityPattern      sparsity_eq, sparsity_compl;

    /**
     * Entries of A below round_off_drop times the scale of the parts that
     * couple them (zero_round_off() with the equilibrium part: at most
     * sqrt(|a_ii a_jj|)) are round-off of an exact zero, far below this and
     * the others far above it (doc/performance.md, "Figures behind the code"), and are
     * dropped.
     */
    static constexpr double round_off_drop = 1e-13;
    LevelVector          rhs_eq, rhs_compl;
    double               constant_eq = 0;

    /** The role of every local DoF (owned and ghost). */
    std::vector<DoFRole> role;
    unsigned int         dimension = 2;
    double               refinement_ratio = 1;
    /** With their ghost values. */
    LevelVector          fixed_values;
    LevelVector          upper_bounds;
    /** With their ghost values; set by FrictionLaw. */
    FrictionTerms        friction;

    /** Whether J has friction terms (collective: the same on every process). */
    bool has_friction() const { return friction.traction_bounds.size() > 0; }
    /** The friction term sum_i w_i |x_i - p_i| of J (0 without friction). Collective. */
    double friction_term(const LevelVector &x) const;

    /**
     * Size A on the level's coupling pattern and copy its roles, fixed
     * values and bounds (a LevelData of the discretization is an
     * AlgebraicLevel). The assembler sizes matrix_eq and matrix_compl on
     * the couplings of their terms (FoslsAssembler::assemble()).
     */
    void reinit(const AlgebraicLevel &level);

    /** The bytes of A, the parts of J, their patterns and the vectors. */
    std::size_t memory_consumption() const;

    /** The number of DoFs (all processes). */
    types::global_dof_index size() const { return rhs.size(); }
    /** The number of owned DoFs (the first local ones). */
    unsigned int n_owned() const { return partitioner->locally_owned_size(); }
    MPI_Comm get_communicator() const { return partitioner->get_mpi_communicator(); }
    /** A zero vector of the level. */
    LevelVector new_vector() const { return LevelVector(partitioner); }

    /**
     * After the owned rows were assembled: drop A's round-off entries
     * (round_off_drop), copy its ghost rows from their owners, and put A,
     * matrix_eq and matrix_compl on patterns of their nonzero entries.
     * @p release_coupling_pattern, if given, frees the coupling pattern
     * (A's pattern until then) as soon as compress_to_nonzeros() no longer
     * reads it; coupling_sparsity is then null.
     */
    void compress_matrices(const std::function<void()> &release_coupling_pattern = {});

    /** J(x). */
    double value(const LevelVector &x) const;
    /** J(x) and its parts. */
    FunctionalValue parts(const LevelVector &x) const;
    /**
     * Set fixed DoFs to their values and cut bounded DoFs at their bound,
     * tractions at their slip bounds (all local entries: with valid ghost
     * values in, valid ones out).
     */
    void project_to_feasible(LevelVector &x) const;
    /** Largest violation of a bound or of a fixed value. */
    double max_violation(const LevelVector &x) const;
    /** Which owned DoFs are bounded and at their bound. */
    std::vector<bool> active_set(const LevelVector &x) const;
    /** Number of bounded DoFs at their bound (all processes). */
    unsigned int n_active(const LevelVector &x) const;
    /** The size of an active set of active_set(), over all processes. */
    unsigned int n_active(const std::vector<bool> &active) const;
    /** KKT residuals at x. */
    KKTResidual kkt_residual(const LevelVector &x) const;
    /**
     * The energy norm sqrt(d^T A d) of a correction d (zero on fixed DoFs,
     * where A is positive definite).
     */
    double energy_norm(const LevelVector &d) const;
    /**
     * The energy norm below which a correction at @p x is made of round-off.
     * The residual b - A x is known only to about eps s_i, with
     * s_i = |b_i| + sum_j |A_ij x_j| the size of the terms of row i. A
     * relaxation turns that into a correction of energy norm about
     * eps sqrt(sum_i s_i^2 / A_ii) (the Jacobi response), and the coarse
     * corrections amplify the smooth part of the noise by up to
     * sqrt(cond A) ~ 1/h_min ~ n^(1/dim) r, with r the refinement ratio of
     * the mesh (AlgebraicLevel::refinement_ratio; 1 on a uniform mesh,
     * whose h_min is about n^(-1/dim)). The estimate is the product of the
     * two; the corrections stop decreasing at a few times this value
     * (doc/performance.md, "Figures behind the code"). Without the
     * factor r the estimate is too low on adaptive meshes, and their
     * solves end only by the stagnation test, after four iterations of
     * noise.
     */
    double round_off_correction(const LevelVector &x) const;
    /**
     * parts() at @p x, energy_norm() of the correction @p d and
     * round_off_correction() at @p x, each the same number the function
     * returns, with one pass over the rows of A instead of three: A is
     * one of the largest structures of a solve (doc/performance.md,
     * section 1), and a pass over it costs more than its arithmetic. This
     * is what the
     * monitor evaluates after every iteration.
     */
    IterateMeasures measure(const LevelVector &x, const LevelVector &d) const;


  private:
    /** parts() at @p x with J(x) = @p total known. */
    FunctionalValue parts_with_total(const LevelVector &x, const double total) const;
    /**
     * round_off_correction() from this process's sum of s_i^2 / A_ii
     * (@p local_sum) and the number of DoFs @p n. Collective.
     */
    double round_off_from(const double local_sum, const types::global_dof_index n) const;
  };
} // namespace FoslsContact

#endif
