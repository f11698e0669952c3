#ifndef fosls_contact_solvers_active_set_direct_h
#define fosls_contact_solvers_active_set_direct_h

#include <fosls_contact/solvers/qp_solver.h>

namespace FoslsContact
{
  /**
   * The reference solver: a primal-dual active set method (Hintermueller,
   * Ito, Kunisch) with a sparse direct solve (Amesos KLU) of the reduced
   * system in every step. It stops when the active set repeats, i.e. at the
   * exact discrete KKT point. The test for the active set,
   * mu_i + c_i (x_i - ub_i) > 0, uses c_i = A_ii so that it is invariant to
   * the scaling of the DoFs. Distributed like the problem: every process
   * tests its own DoFs, the direct solver factorizes the distributed
   * matrix (SparseDirectSolver).
   */
  class ActiveSetDirect : public QPSolver
  {
  public:
    void solve(const ConstrainedQP &qp,
               LevelVector &        x,
               Monitor &            monitor) override;

    /**
     * The same method without a monitor, for small problems (the coarsest
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
      cycling,     ///< an earlier active set came back
      out_of_steps ///< the step limit (or the monitor's) was reached
    };

    /**
     * The method itself, shared by solve() and solve_quietly(): reports
     * every step to @p monitor if there is one; the direct solver
     * factorizes on @p factorization_pattern if given (see
     * SparseDirectSolver::initialize()).
     */
    static Outcome iterate(const SparseMatrix<double> &A,
                           const LevelVector &         b,
                           const std::vector<DoFRole> &role,
                           const LevelVector &         ub,
                           LevelVector &               x,
                           const unsigned int          max_steps,
                           Monitor *                   monitor,
                           const SparsityPattern *     factorization_pattern = nullptr);
  };
} // namespace FoslsContact

#endif
