#include <fosls_contact/qp/sparse_direct_solver.h>

#include <fosls_contact/solvers/active_set_direct.h>

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
      direct.initialize(M);
      direct.vmult(x, rhs);
    }
  } // namespace


  unsigned int
  ActiveSetDirect::solve_quietly(const SparseMatrix<double> &A,
                                 const Vector<double> &      b,
                                 const std::vector<DoFRole> &role,
                                 const Vector<double> &      ub,
                                 Vector<double> &            x,
                                 const unsigned int          max_steps)
  {
    const auto         n = x.size();
    std::vector<bool>  eliminated(n), active(n, false), previous;
    Vector<double>     mu(n), Ax(n);
    unsigned int       step = 0;
    std::set<std::vector<bool>> seen;
    for (; step < max_steps; ++step)
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
          break;
        // A repeated active set means the method cycles: the last solve is
        // the best we have, and the caller sees the KKT residual.
        if (!seen.insert(active).second)
          break;
        previous = active;
        solve_reduced(A, b, eliminated, x);
        A.vmult(Ax, x);
        for (types::global_dof_index i = 0; i < n; ++i)
          mu[i] = active[i] ? b[i] - Ax[i] : 0.;
      }
    return step;
  }


  void
  ActiveSetDirect::solve(const ConstrainedQP &qp,
                         Vector<double> &     x,
                         Monitor &            monitor)
  {
    qp.project_to_feasible(x);
    monitor.start(x);
    const auto        n = x.size();
    std::vector<bool> eliminated(n), active(n, false), previous;
    Vector<double>    mu(n), Ax(n), x_old(x);
    std::set<std::vector<bool>> seen;
    for (unsigned int step = 0;; ++step)
      {
        for (types::global_dof_index i = 0; i < n; ++i)
          {
            if (qp.role[i] == DoFRole::bounded)
              active[i] = mu[i] + qp.matrix.diag_element(i) *
                                    (x[i] - qp.upper_bounds[i]) > 0;
            eliminated[i] = qp.role[i] == DoFRole::fixed || active[i];
            if (active[i])
              x[i] = qp.upper_bounds[i];
          }
        if (step > 0 && active == previous)
          {
            monitor.set_converged();
            break;
          }
        AssertThrow(seen.insert(active).second,
                    ExcMessage("active set: the primal-dual active set method "
                               "cycles (an active set repeated); use Solver/Type "
                               "= monotone multigrid"));
        previous = active;
        x_old    = x;
        solve_reduced(qp.matrix, qp.rhs, eliminated, x);
        qp.matrix.vmult(Ax, x);
        for (types::global_dof_index i = 0; i < n; ++i)
          mu[i] = active[i] ? qp.rhs[i] - Ax[i] : 0.;
        // The iterate of a PDAS step may be infeasible until the last
        // step; report it as it is.
        if (monitor.report(x, x_old) && !monitor.converged())
          break;
      }
  }
} // namespace FoslsContact
