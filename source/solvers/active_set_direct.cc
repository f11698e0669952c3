#include <fosls_contact/qp/sparse_direct_solver.h>

#include <fosls_contact/solvers/active_set_direct.h>

#include <algorithm>
#include <cmath>
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


  ActiveSetDirect::Outcome
  ActiveSetDirect::primal_active_set(const SparseMatrix<double> &A,
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
    const double       eps         = std::numeric_limits<double>::epsilon();
    auto bounded = [&](const unsigned int i) {
      return role[i] == DoFRole::bounded && A.diag_element(i) > 0.;
    };
    // a feasible start, the DoFs at their bound held there (the working set)
    std::vector<bool> working(n_owned, false), eliminated(role.size(), false);
    for (unsigned int i = 0; i < n_owned; ++i)
      if (bounded(i) && x.local_element(i) >= ub.local_element(i))
        {
          x.local_element(i) = ub.local_element(i);
          working[i]         = true;
        }
    LevelVector target(partitioner), Ax(partitioner), x_old;
    for (unsigned int step = 0; step < max_steps; ++step)
      {
        // the minimizer on the face of the working set
        for (unsigned int i = 0; i < n_owned; ++i)
          eliminated[i] = role[i] == DoFRole::fixed || A.diag_element(i) <= 0. || working[i];
        {
          std::vector<unsigned char> e(eliminated.begin(), eliminated.end());
          exchange_ghosts(partitioner, e);
          std::copy(e.begin(), e.end(), eliminated.begin());
        }
        target = x;
        solve_reduced(A, factorization_pattern, b, eliminated, target);
        target -= x; // the direction

        // as far along it as the bounds allow; the bounds that stop it join
        // the working set
        double t = 1.;
        for (unsigned int i = 0; i < n_owned; ++i)
          if (bounded(i) && !working[i] && target.local_element(i) > 0.)
            t = std::min(t,
                         std::max(0., ub.local_element(i) - x.local_element(i)) /
                           target.local_element(i));
        t = Utilities::MPI::min(t, comm);
        if (monitor)
          x_old = x;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double xi = x.local_element(i) + t * target.local_element(i);
            if (bounded(i) && !working[i] && target.local_element(i) > 0. &&
                xi >= ub.local_element(i))
              {
                x.local_element(i) = ub.local_element(i);
                working[i]         = true;
              }
            else
              x.local_element(i) = xi;
          }

        // At the face's minimizer, the bound with the most negative
        // multiplier (scaled to be independent of the DoF's scale) leaves
        // the working set; multipliers within the round-off of their row
        // count as zero (a degenerate bound, whose multiplier is zero at
        // the solution, would otherwise leave and return by round-off).
        bool done = false;
        if (t == 1.)
          {
            vmult(A, Ax, x);
            std::pair<double, types::global_dof_index> release{0., 0};
            for (unsigned int i = 0; i < n_owned; ++i)
              if (working[i])
                {
                  double row = std::abs(b.local_element(i));
                  for (auto e = A.begin(i); e != A.end(i); ++e)
                    row += std::abs(e->value() * x.local_element(e->column()));
                  const double mu = b.local_element(i) - Ax.local_element(i);
                  if (mu < -1e3 * eps * row)
                    release = std::min(release,
                                       std::make_pair(mu / std::sqrt(A.diag_element(i)),
                                                      partitioner->local_to_global(i)));
                }
            // (the same choice on every process: the smallest multiplier,
            // ties to the smallest global index)
            const auto all = gather_all(comm, release);
            release        = *std::min_element(all.begin(), all.end());
            if (release.first < 0.)
              {
                if (partitioner->in_local_range(release.second))
                  working[partitioner->global_to_local(release.second)] = false;
              }
            else
              done = true;
          }
        if (monitor && monitor->report(x, x_old) && !monitor->converged() && !done)
          return Outcome::out_of_steps;
        if (done)
          return Outcome::converged;
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
    Outcome outcome = iterate(A, b, role, ub, x, max_steps, nullptr);
    if (outcome == Outcome::cycling)
      outcome = primal_active_set(A, b, role, ub, x, max_steps, nullptr);
    return outcome == Outcome::converged;
  }


  void
  ActiveSetDirect::solve(const ConstrainedQP &qp,
                         LevelVector &        x,
                         Monitor &            monitor)
  {
    update_ghosts(x);
    qp.project_to_feasible(x);
    monitor.start(x);
    const unsigned int no_limit = std::numeric_limits<unsigned int>::max();
    Outcome            outcome  = iterate(qp.matrix,
                                qp.rhs,
                                qp.role,
                                qp.upper_bounds,
                                x,
                                no_limit,
                                &monitor,
                                qp.coupling_sparsity);
    if (outcome == Outcome::cycling)
      outcome = primal_active_set(qp.matrix,
                                  qp.rhs,
                                  qp.role,
                                  qp.upper_bounds,
                                  x,
                                  no_limit,
                                  &monitor,
                                  qp.coupling_sparsity);
    if (outcome == Outcome::converged)
      monitor.set_converged();
  }
} // namespace FoslsContact
