#include <fosls_contact/qp/gathered_qp.h>
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/coarse_solver.h>

#include <optional>

namespace FoslsContact
{
  void
  CoarseSolver::solve(const Utilities::MPI::Partitioner &partitioner,
                      const SparseMatrix<double> &       A,
                      const unsigned int                 operator_version,
                      const LevelVector &                r,
                      const LevelVector &                ub,
                      const std::vector<DoFRole> &       role,
                      LevelVector &                      v)
  {
    std::optional<ScopedTime> timing;
    if (time != nullptr)
      timing.emplace(*time);
    Assert(v.locally_owned_size() == partitioner.locally_owned_size(),
           ExcMessage("CoarseSolver: a vector of another layout"));
    if (&A != matrix || operator_version != version)
      {
        matrix  = &A;
        version = operator_version;
        set_up(partitioner, A, role);
      }
    if (dofs.empty())
      return;
    gather(partitioner, r, ub, v);
    if (dofs.size() <= max_dense_dofs)
      solve_dense();
    else
      solve_sparse();
    // every process has the whole solution: owned and ghost entries
    for (unsigned int i = 0; i < partitioner.locally_owned_size() + partitioner.n_ghost_indices();
         ++i)
      v.local_element(i) = v_all[partitioner.local_to_global(i)];
  }


  void
  CoarseSolver::set_up(const Utilities::MPI::Partitioner &partitioner,
                       const SparseMatrix<double> &       A,
                       const std::vector<DoFRole> &       role)
  {
    // the owned part of each process, three values per DoF: the whole
    // vectors in global order (each owns a contiguous range, the
    // processes in order)
    const MPI_Comm comm    = partitioner.get_mpi_communicator();
    const auto     n_owned = partitioner.locally_owned_size();
    counts                 = gather_all(comm, int(3 * n_owned));
    displacements.assign(counts.size(), 0);
    for (unsigned int p = 1; p < counts.size(); ++p)
      displacements[p] = displacements[p - 1] + counts[p - 1];
    const auto n = partitioner.size();
    held_factor.reset();
    if (counts.size() == 1)
      {
        // one process: the level's matrix and roles are global already
        // (gathering a copy took as long as its Cholesky factor)
        global = &A;
        role_global.assign(role.begin(), role.begin() + n);
      }
    else
      {
        assemble_gathered_entries(
          gather_all(comm, owned_entries(A.get_sparsity_pattern(), &A, partitioner)),
          n,
          sparsity_global,
          &matrix_global);
        role_global = gathered_roles(gather_all(comm, owned_roles(role, n_owned)));
        global      = &matrix_global;
      }

    // the DoFs that move, and their dense matrix (position: a DoF's place
    // among them)
    dofs.clear();
    std::vector<unsigned int> position(n, numbers::invalid_unsigned_int);
    for (types::global_dof_index i = 0; i < n; ++i)
      if (role_global[i] != DoFRole::fixed && global->diag_element(i) > 0)
        {
          position[i] = dofs.size();
          dofs.push_back(i);
        }
    if (dofs.size() <= max_dense_dofs)
      {
        const unsigned int m = dofs.size();
        FullMatrix<double> dense(m, m);
        for (unsigned int a = 0; a < m; ++a)
          for (auto e = global->begin(dofs[a]); e != global->end(dofs[a]); ++e)
            if (position[e->column()] != numbers::invalid_unsigned_int)
              dense(a, position[e->column()]) = e->value();
        dense_solver.reinit(dense);
      }
  }


  void
  CoarseSolver::gather(const Utilities::MPI::Partitioner &partitioner,
                       const LevelVector &                r,
                       const LevelVector &                ub,
                       const LevelVector &                v)
  {
    // r, ub and v of all processes in one collective, as triples (instead
    // of one collective per vector, each a latency per coarse visit)
    const auto n_owned = partitioner.locally_owned_size();
    const auto n_all   = partitioner.size();
    r_all.reinit(n_all, true);
    ub_all.reinit(n_all, true);
    v_all.reinit(n_all, true);
    owned_triples.resize(3 * n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        owned_triples[3 * i]     = r.local_element(i);
        owned_triples[3 * i + 1] = ub.local_element(i);
        owned_triples[3 * i + 2] = v.local_element(i);
      }
    all_triples.resize(3 * n_all);
    const int ierr = MPI_Allgatherv(owned_triples.data(),
                                    3 * n_owned,
                                    MPI_DOUBLE,
                                    all_triples.data(),
                                    counts.data(),
                                    displacements.data(),
                                    MPI_DOUBLE,
                                    partitioner.get_mpi_communicator());
    AssertThrowMPI(ierr);
    for (unsigned int i = 0; i < n_all; ++i)
      {
        r_all[i]  = all_triples[3 * i];
        ub_all[i] = all_triples[3 * i + 1];
        v_all[i]  = all_triples[3 * i + 2];
      }
  }


  void
  CoarseSolver::solve_dense()
  {
    const unsigned int n = dofs.size();
    g.reinit(n, true);
    s.reinit(n, true);
    c.reinit(n, true);
    Av.reinit(v_all.size(), true);
    global->vmult(Av, v_all);
    for (unsigned int a = 0; a < n; ++a)
      {
        g[a] = r_all[dofs[a]] - Av[dofs[a]];
        s[a] = role_global[dofs[a]] == DoFRole::bounded ?
                 std::max(0., ub_all[dofs[a]] - v_all[dofs[a]]) :
                 std::numeric_limits<double>::infinity();
      }
    dense_solver.solve(g, s, c, at_bound);
    for (unsigned int a = 0; a < n; ++a)
      v_all[dofs[a]] = at_bound[a] ? ub_all[dofs[a]] : v_all[dofs[a]] + c[a];
  }


  void
  CoarseSolver::solve_sparse()
  {
    const unsigned int n = v_all.size();
    // (the first visit of this operator tries the set v is at: a visit of
    // the linear cycle has none, and then this is its solution)
    if (!held_factor)
      hold_where_at_bound();
    if (solve_held())
      return;

    // on this process alone
    const auto  self = serial_partitioner(n);
    LevelVector r_self(self), ub_self(self), v_self(self);
    for (unsigned int i = 0; i < n; ++i)
      {
        r_self.local_element(i)  = r_all[i];
        ub_self.local_element(i) = ub_all[i];
        v_self.local_element(i)  = v_all[i];
      }
    ActiveSetDirect::solve_quietly(*global, r_self, role_global, ub_self, v_self, max_sparse_steps);
    for (unsigned int i = 0; i < n; ++i)
      v_all[i] = v_self.local_element(i);
    // the set it ends with, for the next visits (the active set method
    // sets a held DoF to its bound exactly)
    hold_where_at_bound();
  }


  void
  CoarseSolver::hold_where_at_bound()
  {
    held.assign(v_all.size(), false);
    for (unsigned int i = 0; i < v_all.size(); ++i)
      held[i] = role_global[i] == DoFRole::fixed || global->diag_element(i) <= 0. ||
                (role_global[i] == DoFRole::bounded && v_all[i] >= ub_all[i]);
    // (as the active set method's step, solve_reduced() there)
    SparseMatrix<double> M;
    eliminated_matrix(*global, held, held.size(), M);
    held_factor = std::make_unique<SparseDirectSolver>();
    held_factor->initialize(M, serial_partitioner(held.size()));
    ++n_kept_factorizations;
  }


  bool
  CoarseSolver::solve_held()
  {
    const unsigned int n    = v_all.size();
    const auto         self = serial_partitioner(n);
    LevelVector        x(self), Ax(self);
    // (a bounded DoF with a zero diagonal, switched off by the truncation,
    // is held at v: its bound may be infinite)
    const auto at_bound = [&](const unsigned int i) {
      return held[i] && role_global[i] == DoFRole::bounded && global->diag_element(i) > 0.;
    };
    LevelVector r(self);
    for (unsigned int i = 0; i < n; ++i)
      {
        x.local_element(i) = at_bound(i) ? ub_all[i] : v_all[i];
        r.local_element(i) = r_all[i];
      }
    held_factor->vmult(x, eliminated_rhs(*global, r, x, held));
    // the active set method's test of its set, at x: a held bound stays
    // held where its multiplier b - A x is > 0, a free one where x <= ub
    // (written so that a NaN fails it)
    vmult(*global, Ax, x);
    for (unsigned int i = 0; i < n; ++i)
      if (role_global[i] == DoFRole::bounded && global->diag_element(i) > 0. &&
          !(at_bound(i) ? r_all[i] - Ax.local_element(i) > 0. : x.local_element(i) <= ub_all[i]))
        return false;
    for (unsigned int i = 0; i < n; ++i)
      v_all[i] = x.local_element(i);
    return true;
  }
} // namespace FoslsContact
