#ifndef fosls_contact_solvers_active_set_direct_h
#define fosls_contact_solvers_active_set_direct_h

#include <fosls_contact/solvers/qp_solver.h>

namespace FoslsContact
{
  /**
   * The reference solver: a primal-dual active set method (Hintermueller,
   * Ito, Kunisch) with a sparse direct solve (Amesos KLU) of the reduced
   * system in every step. It stops when the active set repeats, i.e. at the
   * exact discrete KKT point. Should an earlier active set come back instead
   * (the method cycles: possible for a positive definite matrix that is not
   * an M-matrix, and where multipliers and gaps are both zero at the
   * solution, so that round-off decides their signs, as with the
   * obstacle normal (1, 0) on the square), it continues with a primal
   * active set method from its last iterate, which cannot cycle
   * (primal_active_set()). The test for the active set,
   * mu_i + c_i (x_i - ub_i) > 0, uses c_i = A_ii so that it is invariant to
   * the scaling of the DoFs. Distributed like the problem: every process
   * tests its own DoFs, the direct solver factorizes the distributed
   * matrix (SparseDirectSolver). With friction (ConstrainedQP::FrictionTerms)
   * the tangential tractions are held at either slip bound and the slip
   * DoFs stick or slip by the same kind of test (iterate()): the
   * semismooth Newton method of frictional contact, the reference of
   * friction.
   */
  class ActiveSetDirect : public QPSolver
  {
  public:
    void solve(const ConstrainedQP &qp, LevelVector &x, IterationObserver &observer) override;

    /**
     * The same method without an observer, for small problems (the coarsest
     * level of the multigrid method, on one process). DoFs with a zero
     * diagonal are treated as fixed at their value in @p x. Returns whether
     * the active set settled within @p max_steps.
     */
    static bool solve_quietly(const SparseMatrix<double> &matrix,
                              const LevelVector &         rhs,
                              const std::vector<DoFRole> &role,
                              const LevelVector &         upper_bounds,
                              LevelVector &               x,
                              const unsigned int          max_steps);

  private:
    enum class Outcome
    {
      converged,   ///< the active set repeated in consecutive steps
      cycling,     ///< an earlier active set came back (iterate() only)
      out_of_steps ///< the step limit (or the observer's) was reached
    };

    /**
     * The problem min 1/2 x^T A x - b^T x, x_i <= ub_i where role[i] is
     * bounded; the direct solver factorizes on @p factorization_pattern
     * if given (see SparseDirectSolver::initialize()).
     */
    struct Problem
    {
      const SparseMatrix<double> &A;
      const LevelVector &         b;
      const std::vector<DoFRole> &role;
      const LevelVector &         ub;
      const SparsityPattern *     factorization_pattern;
      /** The friction terms, or null (ConstrainedQP::FrictionTerms). */
      const FrictionTerms *       friction;
    };

    /**
     * The method, shared by solve() and solve_quietly(): iterate(), and
     * primal_active_set() from its last iterate if it cycles. Reports
     * every step to @p observer if there is one.
     */
    static Outcome run(const Problem &     problem,
                       LevelVector &       x,
                       const unsigned int  max_steps,
                       IterationObserver * observer);

    /** The primal-dual active set method. */
    static Outcome iterate(const Problem &     problem,
                           LevelVector &       x,
                           const unsigned int  max_steps,
                           IterationObserver * observer);

    /**
     * The fallback where iterate() cycles: a primal active set method
     * (the sparse counterpart of BoxQP). From the feasible point
     * min(x, ub) it minimizes J on the face of its working set (the
     * bounded DoFs held at their bound) with the direct solver, moves
     * towards that minimizer as far as the bounds allow, adds the bounds
     * that stop it to the working set, and at the face's minimizer releases
     * the bound with the most negative multiplier. Every iterate is
     * feasible and every step that releases a bound decreases J strictly,
     * so no working set comes back: it cannot cycle, and ends at the
     * KKT point after finitely many steps. It needs a step per released
     * or added bound (the primal-dual method changes many at once), which
     * from the primal-dual method's last iterate are few.
     */
    static Outcome primal_active_set(const Problem &     problem,
                                     LevelVector &       x,
                                     const unsigned int  max_steps,
                                     IterationObserver * observer);
  };
} // namespace FoslsContact

#endif
