#include <boost/serialization/utility.hpp>

#include <fosls_contact/qp/sparse_direct_solver.h>

#include <fosls_contact/solvers/active_set_direct.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
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
      SparseMatrix<double> M;
      eliminated_matrix(A, eliminated, x.locally_owned_size(), M);
      const LevelVector  rhs = eliminated_rhs(A, b, x, eliminated);
      SparseDirectSolver direct;
      direct.initialize(M, x.get_partitioner(), factorization_pattern);
      direct.vmult(x, rhs);
    }


    /** The owners' flags of @p flags to the ghost entries. */
    void
    exchange_flags(const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
                   std::vector<bool> &                                       flags)
    {
      std::vector<unsigned char> f(flags.begin(), flags.end());
      exchange_ghosts(partitioner, f);
      std::copy(f.begin(), f.end(), flags.begin());
    }


    /**
     * The bound of the working set to release at the minimizer @p x of its
     * face: the most negative multiplier of a held DoF, scaled by
     * 1/sqrt(A_ii) to be independent of the DoF's scale, as (scaled
     * multiplier, global index), the same on every process (ties to the
     * smallest index); (0, 0) if none is negative. @p multiplier(i, g)
     * gives the multiplier of held DoF i from g = (b - A x)_i (for an
     * upper bound g itself; negative: the DoF would move off its bound).
     * Multipliers within the round-off of their row's terms count as zero:
     * a degenerate bound, whose multiplier is zero at the solution, would
     * otherwise leave and return by round-off. Collective.
     */
    template <typename Multiplier>
    std::pair<double, types::global_dof_index>
    bound_to_release(const SparseMatrix<double> &A,
                     const LevelVector &         b,
                     const LevelVector &         x,
                     const std::vector<bool> &   working,
                     const Multiplier &          multiplier)
    {
      const auto &partitioner = *x.get_partitioner();
      LevelVector Ax(x.get_partitioner());
      vmult(A, Ax, x);
      std::pair<double, types::global_dof_index> release{0., 0};
      for (unsigned int i = 0; i < working.size(); ++i)
        if (working[i])
          {
            double row = std::abs(b.local_element(i));
            for (auto e = A.begin(i); e != A.end(i); ++e)
              row += std::abs(e->value() * x.local_element(e->column()));
            const double mu = multiplier(i, b.local_element(i) - Ax.local_element(i));
            if (mu < -1e3 * std::numeric_limits<double>::epsilon() * row)
              release = std::min(release,
                                 std::make_pair(mu / std::sqrt(A.diag_element(i)),
                                                partitioner.local_to_global(i)));
          }
      const auto all = gather_all(partitioner.get_mpi_communicator(), release);
      return *std::min_element(all.begin(), all.end());
    }
  } // namespace


  ActiveSetDirect::Outcome
  ActiveSetDirect::run(const Problem &    problem,
                       LevelVector &      x,
                       const unsigned int max_steps,
                       IterationObserver *observer)
  {
    const Outcome outcome = iterate(problem, x, max_steps, observer);
    return outcome == Outcome::cycling ? primal_active_set(problem, x, max_steps, observer) :
                                         outcome;
  }


  ActiveSetDirect::Outcome
  ActiveSetDirect::iterate(const Problem &    problem,
                           LevelVector &      x,
                           const unsigned int max_steps,
                           IterationObserver *observer)
  {
    const auto &[A, b, role, ub, factorization_pattern, friction] = problem;
    const auto &       partitioner = x.get_partitioner();
    const unsigned int n_owned     = x.locally_owned_size();
    const MPI_Comm     comm        = x.get_mpi_communicator();
    std::vector<bool>  eliminated(role.size(), false);
    // The state of each owned DoF: free, or held at a value (a bound, a
    // slip bound, the reference of a sticking slip DoF), or a slipping
    // slip DoF, free with the term +-w_i in its equation. Friction makes
    // it a semismooth Newton method (Hueber, Stadler, Wohlmuth 2008): a
    // traction DoF is held at +-s_i where x_i + mu_i / c_i lies beyond
    // it, a slip DoF sticks where |x_i - p_i + mu_i / c_i| <= w_i / c_i and
    // slips in the direction of that sign elsewhere.
    enum State : unsigned char
    {
      free,
      at_upper,
      at_lower,
      sticks,
      slips_up,
      slips_down
    };
    std::vector<unsigned char> state(n_owned, free), previous;
    LevelVector        mu(partitioner), Ax(partitioner), x_old, rhs(b);
    // the local active sets of the earlier steps: an active set came back
    // when it came back on every process
    std::vector<std::vector<unsigned char>> seen;
    for (unsigned int step = 0; step < max_steps; ++step)
      {
        rhs = b;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double c  = A.diag_element(i);
            const double xi = x.local_element(i), mi = mu.local_element(i);
            state[i]        = free;
            if (c <= 0.)
              ;
            else if (role[i] == DoFRole::bounded)
              state[i] = mi + c * (xi - ub.local_element(i)) > 0 ? at_upper : free;
            // (a problem without friction terms whose roles have them,
            // the coarse solve of an initial guess: those DoFs are free)
            else if (role[i] == DoFRole::traction && friction != nullptr)
              {
                const double s = friction->traction_bounds.local_element(i);
                const double t = xi + mi / c;
                state[i]       = t > s ? at_upper : t < -s ? at_lower : free;
              }
            else if (role[i] == DoFRole::slip && friction != nullptr)
              {
                const double w = friction->slip_weights.local_element(i);
                const double z = xi - friction->slip_references.local_element(i) + mi / c;
                state[i]       = std::abs(z) <= w / c ? sticks : z > 0 ? slips_up : slips_down;
              }
            switch (state[i])
              {
                case at_upper:
                  x.local_element(i) = role[i] == DoFRole::bounded ?
                                         ub.local_element(i) :
                                         friction->traction_bounds.local_element(i);
                  break;
                case at_lower:
                  x.local_element(i) = -friction->traction_bounds.local_element(i);
                  break;
                case sticks:
                  x.local_element(i) = friction->slip_references.local_element(i);
                  break;
                case slips_up:
                  rhs.local_element(i) -= friction->slip_weights.local_element(i);
                  break;
                case slips_down:
                  rhs.local_element(i) += friction->slip_weights.local_element(i);
                  break;
                default:
                  break;
              }
            eliminated[i] = role[i] == DoFRole::fixed || c <= 0. ||
                            state[i] == at_upper || state[i] == at_lower || state[i] == sticks;
          }
        exchange_flags(partitioner, eliminated);
        const bool unchanged = step > 0 && state == previous;
        if (Utilities::MPI::min(unchanged ? 1u : 0u, comm) == 1)
          return Outcome::converged;
        std::vector<unsigned int> same(seen.size());
        for (unsigned int s = 0; s < seen.size(); ++s)
          same[s] = seen[s] == state ? 1 : 0;
        if (!same.empty())
          {
            const int ierr =
              MPI_Allreduce(MPI_IN_PLACE, same.data(), same.size(), MPI_UNSIGNED, MPI_MIN, comm);
            AssertThrowMPI(ierr);
          }
        if (std::find(same.begin(), same.end(), 1u) != same.end())
          return Outcome::cycling;
        seen.push_back(state);
        previous = state;
        if (observer)
          x_old = x;
        solve_reduced(A, factorization_pattern, rhs, eliminated, x);
        vmult(A, Ax, x);
        // (the multiplier of a held DoF is b - A x; a slipping one's is
        // +-w_i, which is b - A x as well by its equation)
        for (unsigned int i = 0; i < n_owned; ++i)
          mu.local_element(i) =
            state[i] != free ? b.local_element(i) - Ax.local_element(i) : 0.;
        // The iterate of a PDAS step may be infeasible until the last
        // step; it is reported as it is. The observer's own stopping rule
        // does not end the method (only the repeated active set does),
        // its iteration limit does.
        if (observer && observer->report(x, x_old) && !observer->converged())
          return Outcome::out_of_steps;
      }
    return Outcome::out_of_steps;
  }


  ActiveSetDirect::Outcome
  ActiveSetDirect::primal_active_set(const Problem &    problem,
                                     LevelVector &      x,
                                     const unsigned int max_steps,
                                     IterationObserver *observer)
  {
    const auto &[A, b, role, ub, factorization_pattern, friction] = problem;
    const auto &       partitioner = x.get_partitioner();
    const unsigned int n_owned     = x.locally_owned_size();
    constexpr double   inf         = std::numeric_limits<double>::infinity();
    // (a slip DoF of weight 0 has no kink: it is free; a traction of
    // bound 0 is held at 0, and its multiplier is never released: its two
    // bounds are one)
    const auto has = [&](const unsigned int i, const DoFRole r) {
      return role[i] == r && A.diag_element(i) > 0. &&
             (r == DoFRole::bounded ||
              (friction && (r != DoFRole::slip || friction->slip_weights.local_element(i) > 0)));
    };
    // With friction a slip DoF away from its reference moves with the
    // sign of x_i - p_i (sign[i]), the term w_i |x_i - p_i| linear there,
    // and the reference is a bound it stops at (then it sticks: held at
    // p_i, in the working set); a traction is held at either slip bound.
    std::vector<signed char> sign(n_owned, 0);
    const auto lower = [&](const unsigned int i) {
      return has(i, DoFRole::traction) ? -friction->traction_bounds.local_element(i) :
             has(i, DoFRole::slip) && sign[i] > 0 ? friction->slip_references.local_element(i) :
                                                    -inf;
    };
    const auto upper = [&](const unsigned int i) {
      return has(i, DoFRole::bounded)  ? ub.local_element(i) :
             has(i, DoFRole::traction) ? friction->traction_bounds.local_element(i) :
             has(i, DoFRole::slip) && sign[i] < 0 ? friction->slip_references.local_element(i) :
                                                    inf;
    };
    const auto bounded = [&](const unsigned int i) {
      return has(i, DoFRole::bounded) || has(i, DoFRole::traction) || has(i, DoFRole::slip);
    };
    // a feasible start (solve() projected it), the DoFs at a bound held
    // there (the working set)
    std::vector<bool> working(n_owned, false), eliminated(role.size(), false);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        if (has(i, DoFRole::slip))
          {
            const double d = x.local_element(i) - friction->slip_references.local_element(i);
            sign[i]        = d > 0 ? 1 : d < 0 ? -1 : 0;
            working[i]     = d == 0;
          }
        else if (bounded(i))
          {
            const double xi = std::max(lower(i), std::min(x.local_element(i), upper(i)));
            working[i]      = xi == upper(i) || xi == lower(i);
            x.local_element(i) = xi;
          }
      }
    LevelVector direction(partitioner), x_old, rhs(b);
    // Each step puts a bound into the working set (t < 1) or takes one out
    // (t = 1) and lowers J, so that a working set never comes back; in
    // floating point, with a matrix that is not positive definite to
    // working precision (weights many orders apart), the method can go
    // round for ever instead. The bound allows ten passes over the bounds.
    unsigned int n_bounded = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      n_bounded += bounded(i);
    const unsigned int steps =
      std::min<std::uint64_t>(max_steps,
                              10 * (std::uint64_t(Utilities::MPI::sum(
                                      n_bounded, x.get_mpi_communicator())) + 10));
    for (unsigned int step = 0; step < steps; ++step)
      {
        // towards the minimizer on the face of the working set (a slipping
        // DoF's equation with its term +-w_i)
        rhs = b;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            eliminated[i] = role[i] == DoFRole::fixed || A.diag_element(i) <= 0. || working[i];
            if (has(i, DoFRole::slip) && !working[i])
              rhs.local_element(i) -= sign[i] * friction->slip_weights.local_element(i);
          }
        exchange_flags(partitioner, eliminated);
        direction = x;
        solve_reduced(A, factorization_pattern, rhs, eliminated, direction);
        direction -= x;

        // as far as the bounds allow; the bounds that stop it join the
        // working set
        double t = 1.;
        for (unsigned int i = 0; i < n_owned; ++i)
          if (bounded(i) && !working[i])
            {
              const double d = direction.local_element(i), xi = x.local_element(i);
              if (d > 0.)
                t = std::min(t, std::max(0., upper(i) - xi) / d);
              else if (d < 0.)
                t = std::min(t, std::max(0., xi - lower(i)) / -d);
            }
        t = Utilities::MPI::min(t, x.get_mpi_communicator());
        if (observer)
          x_old = x;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double d = direction.local_element(i);
            double       xi = x.local_element(i) + t * d;
            if (bounded(i) && !working[i])
              {
                const bool up = d > 0. && xi >= upper(i), down = d < 0. && xi <= lower(i);
                xi            = up ? upper(i) : down ? lower(i) : xi;
                working[i]    = up || down;
              }
            x.local_element(i) = xi;
          }

        // at the face's minimizer: release a bound, or the KKT point
        bool done = false;
        if (t == 1.)
          {
            // (g = (b - A x)_i: at an upper bound g >= 0 holds it, at a
            // lower one g <= 0; a sticking slip DoF needs |g| <= w_i)
            const auto multiplier = [&](const unsigned int i, const double g) {
              if (has(i, DoFRole::slip))
                return friction->slip_weights.local_element(i) - std::abs(g);
              if (lower(i) == upper(i))
                return inf;
              return x.local_element(i) == lower(i) && lower(i) > -inf ? -g : g;
            };
            const auto release = bound_to_release(A, b, x, working, multiplier);
            if (release.first < 0. && partitioner->in_local_range(release.second))
              {
                const unsigned int i = partitioner->global_to_local(release.second);
                working[i]           = false;
                if (has(i, DoFRole::slip))
                  {
                    // (its g_i, from x's ghost values of bound_to_release())
                    double g = b.local_element(i);
                    for (auto e = A.begin(i); e != A.end(i); ++e)
                      g -= e->value() * x.local_element(e->column());
                    sign[i] = g > 0 ? 1 : -1;
                  }
              }
            done = !(release.first < 0.);
          }
        if (observer && observer->report(x, x_old) && !observer->converged() && !done)
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
    return run({A, b, role, ub, nullptr, nullptr}, x, max_steps, nullptr) == Outcome::converged;
  }


  void
  ActiveSetDirect::solve(const ConstrainedQP &qp,
                         LevelVector &        x,
                         IterationObserver &  observer)
  {
    update_ghosts(x);
    qp.project_to_feasible(x);
    observer.start(x);
    const Outcome outcome =
      run({qp.matrix,
           qp.rhs,
           qp.role,
           qp.upper_bounds,
           qp.coupling_sparsity,
           qp.has_friction() ? &qp.friction : nullptr},
          x,
          std::numeric_limits<unsigned int>::max(),
          &observer);
    if (outcome == Outcome::converged)
      observer.set_converged();
  }
} // namespace FoslsContact
