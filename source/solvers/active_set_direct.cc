#include <fosls_contact/qp/sparse_direct_solver.h>

#include <fosls_contact/solvers/active_set_direct.h>

#include <limits>

namespace FoslsContact
{
  namespace
  {
    /**
     * One step of the primal-dual active set method: solve A x = b on the
     * inactive set, with x fixed on fixed DoFs and x = ub on the active
     * set. The fixed rows and columns are eliminated symmetrically.
     * @p eliminated: all local DoFs (owned and ghost).
     */
    void
    solve_reduced(const SparseMatrix<double> &A,
                  const SparsityPattern *     factorization_pattern,
                  const LevelVector &         b,
                  const std::vector<bool> &   eliminated,
                  LevelVector &               x)
    {
      const auto &       partitioner = x.get_partitioner();
      const unsigned int n_owned     = x.locally_owned_size();
      SparseMatrix<double> M(A.get_sparsity_pattern());
      M.copy_from(A);
      // rhs -= A(:, E) x_E, then identity rows/columns on E.
      LevelVector rhs(b), xe(partitioner), tmp(partitioner);
      for (unsigned int i = 0; i < n_owned; ++i)
        if (eliminated[i])
          xe.local_element(i) = x.local_element(i);
      vmult(A, tmp, xe);
      rhs -= tmp;
      for (unsigned int i = 0; i < n_owned; ++i)
        for (auto e = M.begin(i); e != M.end(i); ++e)
          if (eliminated[i] || eliminated[e->column()])
            e->value() = (i == e->column()) ? 1. : 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        if (eliminated[i])
          rhs.local_element(i) = x.local_element(i);
      SparseDirectSolver direct;
      direct.initialize(M, partitioner, factorization_pattern);
      direct.vmult(x, rhs);
    }
  } // namespace


  ActiveSetDirect::Outcome
  ActiveSetDirect::iterate(const SparseMatrix<double> &A,
                           const LevelVector &         b,
                           const std::vector<DoFRole> &role,
                           const LevelVector &         ub,
                           LevelVector &               x,
                           const unsigned int          max_steps,
                           Monitor *                   monitor,
                           const SparsityPattern *     factorization_pattern)
  {
    const auto &       partitioner = x.get_partitioner();
    const unsigned int n_owned     = x.locally_owned_size();
    const MPI_Comm     comm        = x.get_mpi_communicator();
    std::vector<bool>  eliminated(role.size(), false), active(n_owned, false), previous;
    LevelVector        mu(partitioner), Ax(partitioner), x_old;
    // the local active sets of the earlier steps: an active set came back
    // when it came back on every process
    std::vector<std::vector<bool>> seen;
    for (unsigned int step = 0; step < max_steps; ++step)
      {
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const bool zero_diagonal = A.diag_element(i) <= 0.;
            if (role[i] == DoFRole::bounded && !zero_diagonal)
              active[i] = mu.local_element(i) +
                            A.diag_element(i) * (x.local_element(i) - ub.local_element(i)) >
                          0;
            eliminated[i] = role[i] == DoFRole::fixed || zero_diagonal || active[i];
            if (active[i])
              x.local_element(i) = ub.local_element(i);
          }
        {
          std::vector<unsigned char> e(eliminated.begin(), eliminated.end());
          exchange_ghosts(partitioner, e);
          std::copy(e.begin(), e.end(), eliminated.begin());
        }
        const bool unchanged = step > 0 && active == previous;
        if (Utilities::MPI::min(unchanged ? 1u : 0u, comm) == 1)
          return Outcome::converged;
        std::vector<unsigned int> same(seen.size());
        for (unsigned int s = 0; s < seen.size(); ++s)
          same[s] = seen[s] == active ? 1 : 0;
        if (!same.empty())
          {
            const int ierr =
              MPI_Allreduce(MPI_IN_PLACE, same.data(), same.size(), MPI_UNSIGNED, MPI_MIN, comm);
            AssertThrowMPI(ierr);
          }
        if (std::find(same.begin(), same.end(), 1u) != same.end())
          return Outcome::cycling;
        seen.push_back(active);
        previous = active;
        if (monitor)
          x_old = x;
        solve_reduced(A, factorization_pattern, b, eliminated, x);
        vmult(A, Ax, x);
        for (unsigned int i = 0; i < n_owned; ++i)
          mu.local_element(i) = active[i] ? b.local_element(i) - Ax.local_element(i) : 0.;
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
                                 const LevelVector &         b,
                                 const std::vector<DoFRole> &role,
                                 const LevelVector &         ub,
                                 LevelVector &               x,
                                 const unsigned int          max_steps)
  {
    // A repeated active set means the method cycles: the last solve is the
    // best there is, and the caller's KKT residual shows its quality.
    return iterate(A, b, role, ub, x, max_steps, nullptr) == Outcome::converged;
  }


  void
  ActiveSetDirect::solve(const ConstrainedQP &qp,
                         LevelVector &        x,
                         Monitor &            monitor)
  {
    update_ghosts(x);
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
                ExcMessage(monitor.name() +
                           ": the primal-dual active set method cycles (an active set "
                           "repeated); " +
                           (monitor.name() == "active set" ?
                              "use Solver/Type = monotone multigrid" :
                              "use 'Solver/Initial guess' = zero")));
    if (outcome == Outcome::converged)
      monitor.set_converged();
  }
} // namespace FoslsContact
