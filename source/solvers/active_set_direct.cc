#include <fosls_contact/qp/sparse_direct_solver.h>

#include <fosls_contact/solvers/active_set_direct.h>

#include <limits>
#include <set>

namespace FoslsContact
{
  namespace
  {
    /**
     * One step of the primal-dual active set method: solve A x = b on the
     * inactive set, with x fixed on fixed DoFs and x = ub on the active
     * set. The fixed rows and columns are eliminated symmetrically.
     */
    void
    solve_reduced(const SparseMatrix<double> &A,
                  const SparsityPattern *     factorization_pattern,
                  const Vector<double> &      b,
                  const std::vector<bool> &   eliminated,
                  Vector<double> &            x)
    {
      SparseMatrix<double> M(A.get_sparsity_pattern());
      M.copy_from(A);
      Vector<double> rhs(b);
      // rhs -= A(:, E) x_E, then identity rows/columns on E.
      Vector<double> xe(x.size());
      for (types::global_dof_index i = 0; i < x.size(); ++i)
        if (eliminated[i])
          xe[i] = x[i];
      Vector<double> tmp(x.size());
      A.vmult(tmp, xe);
      rhs -= tmp;
      for (types::global_dof_index i = 0; i < x.size(); ++i)
        for (auto e = M.begin(i); e != M.end(i); ++e)
          if (eliminated[i] || eliminated[e->column()])
            e->value() = (i == e->column()) ? 1. : 0.;
      for (types::global_dof_index i = 0; i < x.size(); ++i)
        if (eliminated[i])
          rhs[i] = x[i];
      SparseDirectSolver direct;
      direct.initialize(M, factorization_pattern);
      direct.vmult(x, rhs);
    }
  } // namespace


  ActiveSetDirect::Outcome
  ActiveSetDirect::iterate(const SparseMatrix<double> &A,
                           const Vector<double> &      b,
                           const std::vector<DoFRole> &role,
                           const Vector<double> &      ub,
                           Vector<double> &            x,
                           const unsigned int          max_steps,
                           Monitor *                   monitor,
                           const SparsityPattern *     factorization_pattern)
  {
    const auto        n = x.size();
    std::vector<bool> eliminated(n), active(n, false), previous;
    Vector<double>    mu(n), Ax(n), x_old;
    std::set<std::vector<bool>> seen;
    for (unsigned int step = 0; step < max_steps; ++step)
      {
        for (types::global_dof_index i = 0; i < n; ++i)
          {
            const bool zero_diagonal = A.diag_element(i) <= 0.;
            if (role[i] == DoFRole::bounded && !zero_diagonal)
              active[i] = mu[i] + A.diag_element(i) * (x[i] - ub[i]) > 0;
            eliminated[i] = role[i] == DoFRole::fixed || zero_diagonal || active[i];
            if (active[i])
              x[i] = ub[i];
          }
        if (step > 0 && active == previous)
          return Outcome::converged;
        if (!seen.insert(active).second)
          return Outcome::cycling;
        previous = active;
        if (monitor)
          x_old = x;
        solve_reduced(A, factorization_pattern, b, eliminated, x);
        A.vmult(Ax, x);
        for (types::global_dof_index i = 0; i < n; ++i)
          mu[i] = active[i] ? b[i] - Ax[i] : 0.;
        // The iterate of a PDAS step may be infeasible until the last
        // step; it is reported as it is. The monitor's own stopping rule
        // does not end the method (only the repeated active set does),
        // its iteration limit does.
        if (monitor && monitor->report(x, x_old) && !monitor->converged())
          return Outcome::out_of_steps;
      }
    return Outcome::out_of_steps;
  }


  bool
  ActiveSetDirect::solve_quietly(const SparseMatrix<double> &A,
                                 const Vector<double> &      b,
                                 const std::vector<DoFRole> &role,
                                 const Vector<double> &      ub,
                                 Vector<double> &            x,
                                 const unsigned int          max_steps)
  {
    // A repeated active set means the method cycles: the last solve is the
    // best there is, and the caller's KKT residual shows its quality.
    return iterate(A, b, role, ub, x, max_steps, nullptr) == Outcome::converged;
  }


  void
  ActiveSetDirect::solve(const ConstrainedQP &qp,
                         Vector<double> &     x,
                         Monitor &            monitor)
  {
    qp.project_to_feasible(x);
    monitor.start(x);
    const Outcome outcome = iterate(qp.matrix,
                                    qp.rhs,
                                    qp.role,
                                    qp.upper_bounds,
                                    x,
                                    std::numeric_limits<unsigned int>::max(),
                                    &monitor,
                                    qp.coupling_sparsity);
    AssertThrow(outcome != Outcome::cycling,
                ExcMessage("active set: the primal-dual active set method "
                           "cycles (an active set repeated); use Solver/Type "
                           "= monotone multigrid"));
    if (outcome == Outcome::converged)
      monitor.set_converged();
  }
} // namespace FoslsContact
