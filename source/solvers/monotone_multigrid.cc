#include <fosls_contact/qp/gathered_qp.h>
#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/coarse_obstacles.h>
#include <fosls_contact/solvers/monotone_multigrid.h>

#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/parallel.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace FoslsContact
{
  template <int dim>
  MonotoneMultigrid<dim>::MonotoneMultigrid(const Discretization<dim> &discretization,
                                            const LevelTransfer<dim> & transfer,
                                            const unsigned int         finest_level,
                                            const SparsityPattern &    fine_sparsity,
                                            const Parameters::Solver & parameters)
    : level_time(finest_level + 1)
    , hierarchy(discretization, transfer, finest_level)
    , parameters(parameters)
    , fine_sparsity(&fine_sparsity)
    , finest(finest_level)
    , smoother(finest_level + 1)
    , prolongation_sparsity(finest_level + 1)
    , face_scale(finest_level + 1)
    , galerkin(finest_level + 1)
    , truncated_prolongation(finest_level + 1)
    , galerkin_product(finest_level + 1)
    , rerouting_import(finest_level + 1)
    , rerouting_entries(finest_level + 1)
    , rerouting_values(finest_level + 1)
    , scratch(finest_level + 1)
    , truncation_used(finest_level + 1)
    , version(finest_level + 1, 0)
    , version_used(finest_level + 1, numbers::invalid_unsigned_int)
    , reroute_used(finest_level + 1, false)
  {
    // The linear cycle's coarsest level: the finest level below the finest
    // with at most linear_coarse_max_dofs DoFs (level 0 if none is).
    for (unsigned int l = 1; l < finest; ++l)
      if (hierarchy.level(l).n_dofs <= linear_coarse_max_dofs)
        linear_coarsest = l;

    // The sparsity patterns of the truncated prolongations (P's pattern
    // plus the entries the flux rerouting may add) and the set-up of their
    // Galerkin products, whose results lie on the coupling patterns of the
    // coarse levels; the solve only recomputes values.
    for (unsigned int l = finest; l > 0; --l)
      {
        const auto &           fine = hierarchy.level(l), &coarse = hierarchy.level(l - 1);
        const SparsityPattern &A  = l == finest ? fine_sparsity : fine.sparsity;
        const SparsityPattern &P0 = hierarchy.prolongation(l).get_sparsity_pattern();
        DynamicSparsityPattern prolongation_dsp(P0.n_rows(), P0.n_cols());
        for (auto e = P0.begin(); e != P0.end(); ++e)
          prolongation_dsp.add(e->row(), e->column());
        for (const auto &[i, j] : hierarchy.rerouting_entries(l))
          prolongation_dsp.add(i, j);
        prolongation_sparsity[l].copy_from(prolongation_dsp);
        face_scale[l].assign(hierarchy.face_relations(l).size(), 1.);

        truncated_prolongation[l].reinit(prolongation_sparsity[l]);
        galerkin_product[l].initialize(
          prolongation_sparsity[l], A, fine.partitioner, coarse.sparsity, coarse.partitioner);
        galerkin[l - 1].reinit(coarse.sparsity);

        // the plain cycle reroutes flux: it reads the operator between the
        // DoFs inside the coarse cells of its contact faces
        if (parameters.krylov_steps == 0)
          {
            const auto requests = rerouting_requests(l);
            rerouting_import[l].reinit(requests, A, fine.partitioner, true);
            for (const auto &[a, b] : requests)
              rerouting_entries[l].emplace_back(fine.partitioner->global_to_local(a),
                                                fine.partitioner->global_to_local(b));
          }
      }
  }


  template <int dim>
  std::vector<MatrixEntryImport::Entry>
  MonotoneMultigrid<dim>::rerouting_requests(const unsigned int l) const
  {
    const auto &                          level = hierarchy.level(l);
    std::vector<MatrixEntryImport::Entry> requests;
    for (const auto &face : hierarchy.face_relations(l))
      for (const auto a : face.inside)
        if (a >= level.n_owned())
          for (const auto b : face.inside)
            requests.emplace_back(level.global(a), level.global(b));
    std::sort(requests.begin(), requests.end());
    requests.erase(std::unique(requests.begin(), requests.end()), requests.end());
    return requests;
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::import_rerouting_values(const unsigned int          l,
                                                  const SparseMatrix<double> &A)
  {
    std::vector<double> values;
    rerouting_import[l].import(A, values);
    rerouting_values[l].clear();
    for (unsigned int k = 0; k < values.size(); ++k)
      rerouting_values[l][rerouting_entries[l][k]] = values[k];
  }


  template <int dim>
  std::map<std::string, QPSolver::SectionTime>
  MonotoneMultigrid<dim>::section_times() const
  {
    return {{"Solve: smoothing", smoothing_time},
            {"Solve: Galerkin operators and patch setup", galerkin_time},
            {"Solve: coarse solve", coarse_time}};
  }


  template <int dim>
  std::vector<QPSolver::SectionTime>
  MonotoneMultigrid<dim>::level_times() const
  {
    std::vector<SectionTime> times(level_time);
    // (level l's visits include those of level l - 1)
    for (unsigned int l = 1; l <= finest; ++l)
      times[l].seconds -= level_time[l - 1].seconds;
    return times;
  }


  template <int dim>
  std::vector<unsigned int>
  MonotoneMultigrid<dim>::n_patch_colors() const
  {
    std::vector<unsigned int> n;
    for (unsigned int l = 1; l <= finest; ++l)
      n.push_back(hierarchy.n_colors(l));
    return n;
  }


  template <int dim>
  bool
  MonotoneMultigrid<dim>::update_coarse_operator(const unsigned int          l,
                                                 const SparseMatrix<double> &A,
                                                 const std::vector<DoFRole> &role,
                                                 const std::vector<bool> &   truncated,
                                                 const bool                  reroute)
  {
    // (truncation_used[l] is empty until the first product); every process
    // takes part in the products, so the decision is taken together
    const bool unchanged = truncated == truncation_used[l] && version[l] == version_used[l] &&
                           reroute == reroute_used[l];
    const MPI_Comm comm = hierarchy.level(l).partitioner->get_mpi_communicator();
    if (Utilities::MPI::min(unchanged ? 1u : 0u, comm) == 1)
      return false;
    const TimedScope timing(galerkin_time);

    // P~: the rows of P at truncated DoFs are zero (its pattern holds P's
    // and the entries flux rerouting may add; both sorted by column)
    SparseMatrix<double> &      Pt = truncated_prolongation[l];
    const SparseMatrix<double> &P  = hierarchy.prolongation(l);
    for_subranges(
      types::global_dof_index(0),
      types::global_dof_index(P.m()),
      [&](const types::global_dof_index begin, const types::global_dof_index end) {
        for (auto r = begin; r < end; ++r)
          {
            auto p = P.begin(r);
            for (auto e = Pt.begin(r); e != Pt.end(r); ++e)
              if (!truncated[r] && p != P.end(r) && p->column() == e->column())
                {
                  e->value() = p->value();
                  ++p;
                }
              else
                e->value() = 0.;
          }
      },
      1000);

    // The coarse faces that go, and the rerouted columns, are decided by
    // the owners of the faces and applied by every process to its rows.
    std::vector<types::global_dof_index> removed;
    std::vector<std::array<double, 3>>   entries; // fine row, coarse column (global), value
    const auto &                         fine   = hierarchy.level(l);
    const auto &                         coarse = hierarchy.level(l - 1);
    if (reroute)
      reroute_flux(l, A, role, truncated, removed, entries);
    else
      {
        // a coarse face with a truncated son goes
        std::fill(face_scale[l].begin(), face_scale[l].end(), 1.);
        for (const auto &face : hierarchy.face_relations(l))
          for (const auto son : face.sons)
            if (truncated[son])
              {
                removed.push_back(coarse.global(face.coarse_dof));
                break;
              }
      }
    std::vector<bool> removed_local(P.n(), false);
    for (const auto &list : gather_all(comm, removed))
      for (const auto j : list)
        if (coarse.partitioner->in_local_range(j) || coarse.partitioner->is_ghost_entry(j))
          removed_local[coarse.partitioner->global_to_local(j)] = true;
    for (const auto &list : gather_all(comm, entries))
      for (const auto &[row, column, value] : list)
        {
          const auto i = static_cast<types::global_dof_index>(row);
          const auto j = static_cast<types::global_dof_index>(column);
          if ((fine.partitioner->in_local_range(i) || fine.partitioner->is_ghost_entry(i)) &&
              (coarse.partitioner->in_local_range(j) || coarse.partitioner->is_ghost_entry(j)))
            Pt.add(fine.partitioner->global_to_local(i),
                   coarse.partitioner->global_to_local(j),
                   value);
        }
    for_subranges(
      types::global_dof_index(0),
      types::global_dof_index(Pt.m()),
      [&](const types::global_dof_index begin, const types::global_dof_index end) {
        for (auto r = begin; r < end; ++r)
          for (auto e = Pt.begin(r); e != Pt.end(r); ++e)
            if (removed_local[e->column()])
              e->value() = 0.;
      },
      1000);

    galerkin_product[l].compute(A, Pt, galerkin[l - 1]);
    // the couplings of coarse functions whose fine couplings cancel (a
    // sixth of the product's nonzeros on the square) would lengthen the
    // patch residuals
    zero_round_off(galerkin[l - 1], coarse.partitioner, ConstrainedQP::round_off_drop);
    coarse.ghost_rows.import_into(galerkin[l - 1]);
    if (parameters.krylov_steps == 0 && l - 1 > 0)
      import_rerouting_values(l - 1, galerkin[l - 1]);
    truncation_used[l] = truncated;
    version_used[l]    = version[l];
    reroute_used[l]    = reroute;
    ++version[l - 1];
    // (not for a level the cycle solves exactly, which it does not smooth;
    // the linear cycle is the one that does not reroute)
    if (!solved_exactly(l - 1, !reroute))
      smoother.initialize_level(l - 1,
                                galerkin[l - 1],
                                hierarchy.patches(l - 1),
                                hierarchy.patch_colors(l - 1),
                                hierarchy.n_colors(l - 1),
                                coarse.role,
                                coarse.partitioner);
    return true;
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::reroute_flux(const unsigned int                    l,
                                       const SparseMatrix<double> &          A,
                                       const std::vector<DoFRole> &          role,
                                       const std::vector<bool> &             truncated,
                                       std::vector<types::global_dof_index> &removed,
                                       std::vector<std::array<double, 3>> &  entries)
  {
    const SparseMatrix<double> &P      = hierarchy.prolongation(l);
    const auto &                faces  = hierarchy.face_relations(l);
    const auto &                fine   = hierarchy.level(l);
    const auto &                coarse = hierarchy.level(l - 1);
    // the operator between DoFs inside the face's coarse cell: own rows
    // here, the others' from the last import
    auto entry = [&](const types::global_dof_index a, const types::global_dof_index b) {
      if (a < fine.n_owned())
        return A.el(a, b);
      const auto it = rerouting_values[l].find({a, b});
      return it == rerouting_values[l].end() ? 0. : it->second;
    };
    for (unsigned int k = 0; k < faces.size(); ++k)
      {
        const auto &face = faces[k];
        const auto  j    = face.coarse_dof;
        face_scale[l][k] = 1.;
        std::vector<types::global_dof_index> free_sons;
        double                               lost = 0;
        for (const auto son : face.sons)
          if (truncated[son])
            lost += P.el(son, j);
          else
            free_sons.push_back(son);
        if (free_sons.size() == face.sons.size())
          continue;
        if (free_sons.empty())
          {
            // no flux can pass: the father goes (a coarse function cut at
            // all its sons would only carry divergence)
            removed.push_back(coarse.global(j));
            continue;
          }

        // d: the change of the column at the sons
        std::map<types::global_dof_index, double> d;
        for (const auto son : face.sons)
          d[son] = truncated[son] ? -P.el(son, j) : lost / free_sons.size();
        for (const auto son : free_sons)
          face_scale[l][k] = std::max(face_scale[l][k], P.el(son, j) + d[son]);

        // the local correction e on the free, unbounded DoFs coupled to the
        // sons inside the coarse cell (so that the column, and the Galerkin
        // operator, stay on the coupling pattern of the coarse cells; with
        // the DoFs on the cell's other faces too, 38 to 114 entries of the
        // coarse operators fell outside it on the square, with the same
        // iterations)
        std::vector<types::global_dof_index> local;
        for (const auto i : face.inside)
          if (!truncated[i] && role[i] == DoFRole::free && d.count(i) == 0 &&
              std::any_of(face.sons.begin(), face.sons.end(), [&](const auto son) {
                return entry(son, i) != 0.;
              }))
            local.push_back(i);
        // (in the global order of the DoFs, the same on every process)
        std::sort(local.begin(), local.end(), [&](const auto a, const auto b) {
          return fine.global(a) < fine.global(b);
        });
        for (const auto &[son, value] : d)
          if (!truncated[son])
            entries.push_back({{double(fine.global(son)), double(coarse.global(j)), value}});
        if (local.empty())
          continue;
        const unsigned int n = local.size();
        FullMatrix<double> A_local(n, n);
        Vector<double>     rhs(n), e(n);
        for (unsigned int a = 0; a < n; ++a)
          {
            for (unsigned int b = 0; b < n; ++b)
              A_local(a, b) = entry(local[a], local[b]);
            for (const auto &[son, value] : d)
              rhs[a] -= entry(local[a], son) * value;
          }
        // gauss_jordan pivots (FullMatrix::invert uses cofactor formulas for
        // n <= 4, see BoxQP)
        A_local.gauss_jordan();
        A_local.vmult(e, rhs);
        for (unsigned int a = 0; a < n; ++a)
          entries.push_back({{double(fine.global(local[a])), double(coarse.global(j)), e[a]}});
      }
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::coarse_solve(const unsigned int          l,
                                       const SparseMatrix<double> &A,
                                       const LevelVector &         r,
                                       const LevelVector &         ub,
                                       const std::vector<DoFRole> &role,
                                       LevelVector &               v)
  {
    const TimedScope timing(coarse_time);
    // (the level's partitioner, not v's: every process takes part)
    const auto &   partitioner = *hierarchy.level(l).partitioner;
    const MPI_Comm comm        = partitioner.get_mpi_communicator();
    Assert(v.locally_owned_size() == partitioner.locally_owned_size(),
           ExcMessage("monotone multigrid: coarse vector of another layout"));
    const auto     n_owned     = partitioner.locally_owned_size();
    if (&A != coarse_matrix || version[l] != coarse_version)
      {
        // set up once per coarse operator (DenseCoarseSolver): it changes
        // only with the truncation, while the W-cycles of a Newton step
        // visit it hundreds of times
        coarse_matrix  = &A;
        coarse_version = version[l];
        // the owned part of each process, three values per DoF: the whole
        // vectors in global order (each owns a contiguous range, the
        // processes in order)
        coarse_counts = gather_all(comm, int(3 * n_owned));
        coarse_displacements.assign(coarse_counts.size(), 0);
        for (unsigned int p = 1; p < coarse_counts.size(); ++p)
          coarse_displacements[p] = coarse_displacements[p - 1] + coarse_counts[p - 1];
        const auto n = partitioner.size();
        if (coarse_counts.size() == 1)
          {
            // one process: the level's matrix and roles are global already
            // (gathering a copy took 0.2 ms on the square's level 2, 130
            // DoFs, as long as its Cholesky factor; by hand)
            coarse_global = &A;
            coarse_role_global.assign(role.begin(), role.begin() + n);
          }
        else
          {
            assemble_gathered_entries(
              gather_all(comm, owned_entries(A.get_sparsity_pattern(), &A, partitioner)),
              n,
              coarse_sparsity_global,
              &coarse_matrix_global);
            coarse_role_global = gathered_roles(gather_all(comm, owned_roles(role, n_owned)));
            coarse_global = &coarse_matrix_global;
          }

        // the DoFs that move, and their dense matrix (position: a DoF's
        // place among them)
        coarse_dofs.clear();
        std::vector<unsigned int> position(n, numbers::invalid_unsigned_int);
        for (types::global_dof_index i = 0; i < n; ++i)
          if (coarse_role_global[i] != DoFRole::fixed && coarse_global->diag_element(i) > 0)
            {
              position[i] = coarse_dofs.size();
              coarse_dofs.push_back(i);
            }
        if (coarse_dofs.size() <= 2000)
          {
            const unsigned int m = coarse_dofs.size();
            FullMatrix<double> dense(m, m);
            for (unsigned int a = 0; a < m; ++a)
              for (auto e = coarse_global->begin(coarse_dofs[a]);
                   e != coarse_global->end(coarse_dofs[a]);
                   ++e)
                if (position[e->column()] != numbers::invalid_unsigned_int)
                  dense(a, position[e->column()]) = e->value();
            coarse_dense_solver.reinit(dense);
          }
      }
    const auto &       dofs = coarse_dofs;
    const unsigned int n    = dofs.size();
    if (n == 0)
      return;
    // (into kept arrays: a W-cycle visits the coarse level hundreds of
    // times per Newton step; on level 5 of the square, by hand, a coarse
    // solve took 4.0 us with them and 4.7 us with arrays allocated per call)
    auto &work   = coarse_work;
    // r, ub and v of all processes in one collective, as triples (instead
    // of one collective per vector: the coarse solves of the square's
    // level 5 on 2 processes took 0.08 ms less per solve, 18 visits, by
    // hand)
    const auto n_all = partitioner.size();
    work.r_all.reinit(n_all, true);
    work.ub_all.reinit(n_all, true);
    work.v_all.reinit(n_all, true);
    work.owned_triples.resize(3 * n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        work.owned_triples[3 * i]     = r.local_element(i);
        work.owned_triples[3 * i + 1] = ub.local_element(i);
        work.owned_triples[3 * i + 2] = v.local_element(i);
      }
    work.all_triples.resize(3 * n_all);
    const int ierr = MPI_Allgatherv(work.owned_triples.data(),
                                    3 * n_owned,
                                    MPI_DOUBLE,
                                    work.all_triples.data(),
                                    coarse_counts.data(),
                                    coarse_displacements.data(),
                                    MPI_DOUBLE,
                                    comm);
    AssertThrowMPI(ierr);
    for (unsigned int i = 0; i < n_all; ++i)
      {
        work.r_all[i]  = work.all_triples[3 * i];
        work.ub_all[i] = work.all_triples[3 * i + 1];
        work.v_all[i]  = work.all_triples[3 * i + 2];
      }
    const auto &r_all = work.r_all, &ub_all = work.ub_all;
    auto &      v_all = work.v_all;
    if (n <= 2000)
      {
        auto &g = work.g, &s = work.s, &c = work.c, &Av = work.Av;
        g.reinit(n, true);
        s.reinit(n, true);
        c.reinit(n, true);
        Av.reinit(v_all.size(), true);
        coarse_global->vmult(Av, v_all);
        for (unsigned int a = 0; a < n; ++a)
          {
            g[a] = r_all[dofs[a]] - Av[dofs[a]];
            s[a] = coarse_role_global[dofs[a]] == DoFRole::bounded ?
                     std::max(0., ub_all[dofs[a]] - v_all[dofs[a]]) :
                     std::numeric_limits<double>::infinity();
          }
        coarse_dense_solver.solve(g, s, c, work.at_bound);
        for (unsigned int a = 0; a < n; ++a)
          v_all[dofs[a]] = work.at_bound[a] ? ub_all[dofs[a]] : v_all[dofs[a]] + c[a];
      }
    else
      {
        // a large coarse mesh: the sparse primal-dual active set method, on
        // this process alone
        const auto self = serial_partitioner(v_all.size());
        LevelVector r_self(self), ub_self(self), v_self(self);
        for (unsigned int i = 0; i < v_all.size(); ++i)
          {
            r_self.local_element(i)  = r_all[i];
            ub_self.local_element(i) = ub_all[i];
            v_self.local_element(i)  = v_all[i];
          }
        ActiveSetDirect::solve_quietly(
          *coarse_global, r_self, coarse_role_global, ub_self, v_self, 100);
        for (unsigned int i = 0; i < v_all.size(); ++i)
          v_all[i] = v_self.local_element(i);
      }
    // every process has the whole solution: owned and ghost entries
    for (unsigned int i = 0; i < partitioner.locally_owned_size() + partitioner.n_ghost_indices(); ++i)
      v.local_element(i) = v_all[partitioner.local_to_global(i)];
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::cycle(const unsigned int          l,
                                const SparseMatrix<double> &A,
                                const LevelVector &         r,
                                const LevelVector &         ub,
                                const std::vector<DoFRole> &role,
                                LevelVector &               v,
                                const bool                  linear,
                                std::optional<Parameters::Solver::Cycle> type)
  {
    using Cycle = Parameters::Solver::Cycle;
    if (!type)
      type = parameters.cycle;
    const TimedScope level_timing(level_time[l]);
    if (solved_exactly(l, linear))
      {
        coarse_solve(l, A, r, ub, role, v);
        return;
      }

    // the finest level of the linear cycle relaxes with the linear roles
    // (on coarser levels the truncation takes care of them)
    smoother.use_linear_roles(l, linear && l == finest);
    smoother.set_obstacles(l, ub);
    smoother.set_backward(false);
    smoother.set_steps(parameters.pre_smoothing);
    {
      const TimedScope timing(smoothing_time);
      smoother.smooth(l, v, r); // (v's ghost values are valid afterwards)
    }

    const double       inf         = std::numeric_limits<double>::infinity();
    const auto &       fine        = hierarchy.level(l);
    const auto &       coarse      = hierarchy.level(l - 1);
    // (an exact coarse solve needs one visit)
    const unsigned int visits = solved_exactly(l - 1, linear) || *type == Cycle::V ? 1 : 2;
    const unsigned int n_local     = fine.n_local();
    const unsigned int n_owned     = fine.n_owned();
    // the work vectors of this level (a level is never visited twice at
    // once, and allocating them per visit showed up as page faults)
    Scratch &          work        = scratch[l];
    auto &             defect      = work.defect;
    // (set up on the first visit; a process may own no DoF of the level,
    // so the size of the arrays cannot tell whether they are: the vectors'
    // partitioners can, and without them the vectors would live on
    // MPI_COMM_SELF and the coarse solve's collectives would skip this
    // process)
    if (work.defect.get_partitioner() != fine.partitioner)
      {
        work.truncated.resize(n_local);
        work.defect.reinit(fine.partitioner);
        work.residual.reinit(fine.partitioner);
        work.w.reinit(fine.partitioner);
        work.r_coarse.reinit(coarse.partitioner);
        work.ub_coarse.reinit(coarse.partitioner);
        work.c.reinit(coarse.partitioner);
        work.Ac.reinit(coarse.partitioner);
      }
    if (work.diagonal_version != operator_version(l, A))
      {
        // (the same on every process: the diagonal has ghost values)
        work.diagonal         = diagonal(A, fine.partitioner);
        update_ghosts(work.diagonal); // (an assignment copies the owned entries only)
        work.diagonal_version = operator_version(l, A);
      }
    if (work.operator_version != operator_version(l, A) || work.role != role)
      {
        // The part of the truncation that does not depend on the iterate:
        // fixed DoFs, and DoFs whose diagonal is zero, switched off by the
        // truncation of the finer level. It changes only with the
        // operator (which changes only with that truncation) or the roles
        // (those of the Newton step's linear problem), so a visit only
        // looks at the bounded DoFs.
        work.fixed_truncated.resize(n_local);
        work.bounded.clear();
        for (unsigned int i = 0; i < n_local; ++i)
          {
            work.fixed_truncated[i] =
              role[i] == DoFRole::fixed || work.diagonal.local_element(i) <= 0;
            if (role[i] == DoFRole::bounded && !work.fixed_truncated[i])
              work.bounded.push_back(i);
            defect.local_element(i) = inf;
          }
        work.operator_version = operator_version(l, A);
        work.role             = role;
      }
    auto &truncated = work.truncated;
    auto &residual  = work.residual;
    auto &w         = work.w;
    auto &r_coarse  = work.r_coarse;
    auto &ub_coarse = work.ub_coarse;
    auto &c         = work.c;
    auto &Ac        = work.Ac;
    const MPI_Comm comm = fine.partitioner->get_mpi_communicator();

    double alpha = 1.; // the damping of the last visit's correction
    for (unsigned int visit = 0; visit < visits; ++visit)
      {
        // Truncation (eq. 34): fixed, active and switched-off DoFs do not
        // move; their defect obstacle is +inf (eqs. 35-36). On the ghost
        // DoFs too, from their owners' values: the same decision. (The
        // ghost values of v and ub are valid after the smoothing above; v
        // changes in a visit.)
        if (visit > 0)
          update_ghosts(v);
        truncated = work.fixed_truncated;
        for (const auto i : work.bounded)
          {
            const double vi = v.local_element(i), ubi = ub.local_element(i);
            truncated[i]            = vi >= ubi; // active
            defect.local_element(i) = truncated[i] ? inf : ubi - vi;
          }
        const bool rebuilt = update_coarse_operator(l, A, role, truncated, !linear);
        const auto &P       = truncated_prolongation[l];

        if (visit == 0 || rebuilt)
          restrict_defect(l, A, r, v, residual, r_coarse);
        else
          {
            // The truncation is the one of the last visit (always so in the
            // Newton step's linear cycle), so the coarse operator is
            // P~^T A P~ with the same P~, and the coarse defect of
            // v + alpha P~ c is P~^T (r - A v) - alpha P~^T A P~ c =
            // r_coarse - alpha A_{l-1} c, with A_{l-1} c from the last visit:
            // no product with the fine matrix and P~. (The same up to
            // round-off: the square's cycles and J unchanged on levels 5-9,
            // solves 2% (level 5) to 7% (level 7) faster on one thread, by
            // hand.)
            r_coarse.add(-alpha, Ac);
            if (parameters.check_coarse_defects)
              check_coarse_defect(l, A, r, v, r_coarse);
          }
        CoarseObstacles::project(
          parameters.projection, hierarchy.face_relations(l), face_scale[l], defect, ub_coarse);
        c = 0;
        // (an F-cycle: an F-cycle on the first visit, a V-cycle on the
        // second)
        cycle(l - 1,
              galerkin[l - 1],
              r_coarse,
              ub_coarse,
              coarse.role,
              c,
              linear,
              *type == Cycle::F && visit == 1 ? Cycle::V : *type);

        // (c's ghost values are valid after the coarse cycle)
        vmult(P, w, c, false);
        // keep the iterate feasible (a no-op when K_H is inside K_h)
        alpha = 1.;
        for (const auto i : work.bounded)
          if (i < n_owned && !truncated[i])
            {
              const double wi = w.local_element(i), vi = v.local_element(i),
                           ubi = ub.local_element(i);
              if (wi > 0 && vi + wi > ubi)
                alpha = std::min(alpha, std::max(0., (ubi - vi) / wi));
            }
        alpha = Utilities::MPI::min(alpha, comm);
        if (alpha < 1.)
          ++n_dampings;

        // the change of Q_l: -alpha w.residual + alpha^2/2 w.A w, with
        // w = P~ c: w.residual = c.r_coarse and w.A w = c.A_{l-1} c (the
        // Galerkin product), on the coarse level instead of a product with
        // the fine matrix
        vmult(galerkin[l - 1], Ac, c, false);
        const double wr = c * r_coarse, wAw = c * Ac;
        const double change = -alpha * wr + 0.5 * alpha * alpha * wAw;
        if (change > 1e-10 * (std::abs(alpha * wr) + 0.5 * alpha * alpha * std::abs(wAw)) + 1e-300)
          ++n_increases;
        v.add(alpha, w);
        for (const auto i : work.bounded)
          if (i < n_owned && v.local_element(i) > ub.local_element(i))
            v.local_element(i) = ub.local_element(i); // round-off of the damped step only
      }

    smoother.use_linear_roles(l, linear && l == finest);
    smoother.set_obstacles(l, ub);
    smoother.set_backward(true);
    smoother.set_steps(parameters.post_smoothing);
    {
      const TimedScope timing(smoothing_time);
      smoother.smooth(l, v, r);
    }
    smoother.use_linear_roles(l, false);
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::restrict_defect(const unsigned int          l,
                                          const SparseMatrix<double> &A,
                                          const LevelVector &         r,
                                          const LevelVector &         v,
                                          LevelVector &               residual,
                                          LevelVector &               r_coarse) const
  {
    vmult(A, residual, v, false); // (v's ghosts: valid in a visit)
    residual.sadd(-1., 1., r);
    galerkin_product[l].Tvmult(r_coarse, residual);
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::check_coarse_defect(const unsigned int          l,
                                              const SparseMatrix<double> &A,
                                              const LevelVector &         r,
                                              const LevelVector &         v,
                                              const LevelVector &         r_coarse)
  {
    LevelVector residual(r), difference(r_coarse);
    restrict_defect(l, A, r, v, residual, difference);
    difference -= r_coarse;
    const MPI_Comm comm = r.get_partitioner()->get_mpi_communicator();
    const double   bound =
      Utilities::MPI::max(truncated_prolongation[l].l1_norm(), comm) *
      (Utilities::MPI::max(A.linfty_norm(), comm) * v.linfty_norm() + r.linfty_norm());
    // (linfty_norm() may drop a NaN, the l2 norm keeps it; once NaN, the
    // result stays NaN, which std::max would drop)
    const double size = difference.l2_norm();
    const double d    = !std::isfinite(size) || !std::isfinite(bound) ?
                          std::numeric_limits<double>::quiet_NaN() :
                        bound > 0 ? difference.linfty_norm() / bound :
                        size > 0  ? std::numeric_limits<double>::infinity() :
                                    0.;
    ++n_coarse_defect_checks;
    if (!std::isnan(coarse_defect_difference) && (std::isnan(d) || d > coarse_defect_difference))
      coarse_defect_difference = d;
  }


  namespace
  {
    /**
     * A restricted to the inactive set: the rows and columns of the fixed
     * DoFs are 0 (@p fixed: the owned ones).
     */
    struct TruncatedOperator
    {
      const SparseMatrix<double> &                A;
      const std::vector<types::global_dof_index> &fixed;
      mutable LevelVector                         tmp;
      void
      vmult(LevelVector &dst, const LevelVector &src) const
      {
        tmp = src;
        for (const auto i : fixed)
          tmp.local_element(i) = 0;
        FoslsContact::vmult(A, dst, tmp);
        for (const auto i : fixed)
          dst.local_element(i) = 0;
      }
    };

    /** The linear truncated cycle as a preconditioner. */
    template <typename Cycle>
    struct CyclePreconditioner
    {
      Cycle cycle;
      void
      vmult(LevelVector &dst, const LevelVector &src) const
      {
        dst = 0;
        cycle(src, dst);
      }
    };
  } // namespace


  template <int dim>
  unsigned int
  MonotoneMultigrid<dim>::newton_step(const ConstrainedQP &qp, LevelVector &x)
  {
    unsigned int   n_cycles = 0;
    const auto &   A        = qp.matrix;
    const auto     n_owned  = qp.n_owned();
    const auto     n_local  = qp.role.size();
    const MPI_Comm comm     = qp.get_communicator();

    smoother.set_obstacles(finest, qp.upper_bounds);
    smoother.set_backward(false);
    smoother.set_steps(parameters.pre_smoothing);
    {
      const TimedScope timing(smoothing_time);
      smoother.smooth(finest, x, qp.rhs);
    }

    // The linear problem keeps a DoF at its bound only where the bound
    // holds it: the multiplier mu_i = (b - A x)_i is positive. A DoF that
    // sits at its bound while the gradient pulls it inside (mu_i < 0) is
    // left free, so that the Newton direction can release it.
    LevelVector residual = qp.new_vector(), d = qp.new_vector(), increment = qp.new_vector(),
                rhs = qp.new_vector(), Ae = qp.new_vector();
    vmult(A, residual, x, false); // (x's ghosts: after the smoothing)
    residual.sadd(-1., 1., qp.rhs);
    update_ghosts(residual);
    linear_role = qp.role;
    for (unsigned int i = 0; i < n_local; ++i)
      if (qp.role[i] == DoFRole::bounded)
        linear_role[i] = (x.local_element(i) >= qp.upper_bounds.local_element(i) &&
                          residual.local_element(i) >= 0) ?
                           DoFRole::fixed :
                           DoFRole::free;

    LevelVector infinite = qp.new_vector();
    infinite             = std::numeric_limits<double>::infinity();
    auto apply_cycle     = [&](const LevelVector &r, LevelVector &v) {
      cycle(finest, A, r, infinite, linear_role, v, true);
      ++n_cycles;
    };
    CyclePreconditioner<decltype(apply_cycle)> preconditioner{apply_cycle};
    std::vector<types::global_dof_index> fixed;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (linear_role[i] == DoFRole::fixed)
        fixed.push_back(i);
    TruncatedOperator op{A, fixed, qp.new_vector()};

    // The Newton direction d = increment + (solution of the linear problem
    // on the free DoFs). A free DoF that the direction would push past its
    // bound is moved exactly to its bound instead (a prescribed increment)
    // and the linear problem is solved again without it, as in a
    // primal-dual active set step: otherwise the projection in the line
    // search cuts such a DoF back, and the rest of the direction, computed
    // for it moving on, is far from a good step (measured on the graded
    // half disc, prm/hertz.prm with 4 levels and Grading 2: two such DoFs
    // made the projected step's energy 1e6 times its decrease, and the run
    // took 49 iterations). Each round fixes at least one more DoF, so the
    // rounds end; they are capped all the same. A cap of 3 rounds was too
    // low where the contact zone grows by a vertex per round: half disc, 5
    // levels, 20 iterations (264 cycles, 26.6 s) against 6 (111 cycles,
    // 11.2 s) with up to 10 rounds, the same with 30 (by hand).
    const unsigned int max_rounds = 20;
    // The linear solves of all rounds stop at 1e-3 times the norm of the
    // first round's right-hand side (the residual on the free DoFs), not of
    // their own: a DoF moved to its bound puts a large, local residual next
    // to it, which one cycle removes, and a tolerance relative to that norm
    // stopped CG after 1 step with the smooth part of the error untouched.
    // The direction was then so far off that the best step along it was
    // 0.2 d, every iteration (by hand: the square [-1,1]x[0,1] with gap
    // 0.02 - 0.015 x^2, 5 levels, stalled at rate 0.993 with J 2.6 times
    // its minimum after 200 iterations; with this tolerance, 3 iterations).
    double tolerance = 0;
    for (unsigned int round = 0; round < max_rounds + 1; ++round)
      {
        if (linear_role != linear_role_used)
          {
            const TimedScope timing(galerkin_time);
            smoother.set_linear_roles(finest, linear_role);
            linear_role_used = linear_role;
          }
        rhs = residual;
        if (round > 0) // the increment is zero until a DoF was moved to its bound
          {
            vmult(A, Ae, increment);
            rhs -= Ae;
          }
        for (unsigned int i = 0; i < n_owned; ++i)
          if (linear_role[i] == DoFRole::fixed)
            rhs.local_element(i) = 0;
        if (round == 0)
          tolerance = 1e-3 * rhs.l2_norm();
        SolverControl control(parameters.krylov_steps, tolerance, false, false);
        SolverCG<LevelVector> cg(control);
        d = 0;
        try
          {
            cg.solve(op, d, rhs, preconditioner);
          }
        catch (const SolverControl::NoConvergence &)
          {
            // at most krylov_steps steps: the last iterate is the direction
          }
        d += increment;
        bool violated = false;
        for (unsigned int i = 0; round < max_rounds && i < n_owned; ++i)
          if (qp.role[i] == DoFRole::bounded && linear_role[i] == DoFRole::free &&
              x.local_element(i) + d.local_element(i) > qp.upper_bounds.local_element(i))
            {
              linear_role[i] = DoFRole::fixed;
              fixed.push_back(i);
              increment.local_element(i) =
                qp.upper_bounds.local_element(i) - x.local_element(i);
              violated = true;
            }
        if (Utilities::MPI::max(violated ? 1u : 0u, comm) == 0)
          break;
        // the owners' decisions to the ghost copies (the smoother's roles)
        exchange_ghosts(qp.partitioner, linear_role);
      }

    // Line search: two feasible steps that decrease J; the one that
    // decreases it more is taken (the same on every process: the decreases
    // are sums over all of them).
    // a) The feasible part of the step along d: x + t d with t the minimizer
    //    alpha* = d.r / d.A.d, cut back to the largest t with x + t d in K
    //    (J decreases by convexity). After the rounds above x + d is in K,
    //    with the DoFs they fixed exactly at their bound.
    // b) The projected Newton step p = P_K(x + alpha* d): every point of the
    //    segment [x, p] is feasible (K is convex) and J is a quadratic on
    //    it, so its minimizer t in (0, 1] is taken when p - x is a descent
    //    direction.
    // b) alone is not enough: where the DoFs fixed by the rounds have
    //    positive multipliers, alpha* > 1, and p cuts them back to their
    //    bound while the rest of p moves on as if they did not. Measured on
    //    the graded half disc (prm/hertz.prm, Grading 2, 5 levels): p - x
    //    had 85 to 1300 times the energy of d, the step along it decreased J
    //    70 to 500 times less than x + d, the two DoFs stayed 7.7e-3 away
    //    from their bound, and the run stalled (200 iterations, rate 0.996
    //    per cycle; with both steps: 10 iterations, 182 cycles).
    LevelVector Ad = qp.new_vector(), step = qp.new_vector();
    vmult(A, Ad, d);
    const double dAd = d * Ad, dr = d * residual;
    if (!(dAd > 0) || !(dr > 0))
      return n_cycles;
    auto step_to_bound = [&](const unsigned int i) {
      return std::max(0.,
                      (qp.upper_bounds.local_element(i) - x.local_element(i)) /
                        d.local_element(i));
    };
    double t_d = dr / dAd;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (qp.role[i] == DoFRole::bounded && d.local_element(i) > 0)
        t_d = std::min(t_d, step_to_bound(i));
    t_d                     = Utilities::MPI::min(t_d, comm);
    const double decrease_d = t_d * (dr - 0.5 * t_d * dAd);

    step = x;
    step.add(dr / dAd, d);
    qp.project_to_feasible(step);
    step -= x;
    LevelVector As = qp.new_vector();
    vmult(A, As, step);
    const double sAs = step * As, sr = step * residual;
    double       t_p = 0, decrease_p = 0;
    if (sAs > 0 && sr > 0)
      {
        t_p        = std::min(1., sr / sAs);
        decrease_p = t_p * (sr - 0.5 * t_p * sAs);
      }
    if (decrease_p > decrease_d)
      x.add(t_p, step);
    else
      {
        // the DoFs that limit t_d end exactly at their bound (not a
        // rounding below it, which would leave them inactive)
        std::vector<unsigned int> limiting;
        for (unsigned int i = 0; i < n_owned; ++i)
          if (qp.role[i] == DoFRole::bounded && d.local_element(i) > 0 &&
              step_to_bound(i) <= t_d)
            limiting.push_back(i);
        x.add(t_d, d);
        for (const auto i : limiting)
          x.local_element(i) = qp.upper_bounds.local_element(i);
      }
    qp.project_to_feasible(x); // round-off only

    smoother.set_obstacles(finest, qp.upper_bounds);
    smoother.set_backward(true);
    smoother.set_steps(parameters.post_smoothing);
    {
      const TimedScope timing(smoothing_time);
      smoother.smooth(finest, x, qp.rhs);
    }
    return n_cycles;
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::solve(const ConstrainedQP &qp,
                                LevelVector &        x,
                                Monitor &            monitor)
  {
    AssertThrow(qp.size() == hierarchy.level(finest).n_dofs,
                ExcMessage("monotone multigrid: problem and hierarchy differ"));
    AssertThrow(&qp.matrix.get_sparsity_pattern() == fine_sparsity &&
                  fine_sparsity->n_nonzero_elements() == qp.matrix.n_nonzero_elements(),
                ExcMessage("monotone multigrid: the problem's matrix is not on the "
                           "pattern the solver was set up for"));
    update_ghosts(x);
    qp.project_to_feasible(x);
    monitor.enable_stall_detection();
    monitor.start(x);
    {
      const TimedScope timing(galerkin_time);
      smoother.initialize_level(finest,
                                qp.matrix,
                                hierarchy.patches(finest),
                                hierarchy.patch_colors(finest),
                                hierarchy.n_colors(finest),
                                qp.role,
                                qp.partitioner);
    }
    if (parameters.krylov_steps == 0 && finest > 0)
      import_rerouting_values(finest, qp.matrix);
    linear_role_used.clear(); // the linear roles of the finest level are gone
    ++version[finest];

    LevelVector x_old(x);
    for (;;)
      {
        x_old = x;
        const unsigned int increases_before =
          n_increases + Utilities::MPI::sum(smoother.energy_increases(), qp.get_communicator());
        const unsigned int dampings_before = n_dampings;
        if (finest == 0)
          {
            // one level: the exact coarse solve is the whole method
            cycle(0, qp.matrix, qp.rhs, qp.upper_bounds, qp.role, x);
            monitor.report(x, x_old);
            monitor.set_converged();
            break;
          }
        else if (parameters.krylov_steps > 0)
          // the fine-level projected smoothing counts as one more cycle
          monitor.note_cycles(newton_step(qp, x) + 1);
        else
          {
            cycle(finest, qp.matrix, qp.rhs, qp.upper_bounds, qp.role, x);
            monitor.note_cycles(1);
          }
        const unsigned int increases_after =
          n_increases + Utilities::MPI::sum(smoother.energy_increases(), qp.get_communicator());
        for (unsigned int k = increases_before; k < increases_after; ++k)
          monitor.note_energy_increase();
        for (unsigned int k = dampings_before; k < n_dampings; ++k)
          monitor.note_feasibility_damping();
        if (monitor.report(x, x_old))
          break;
      }
  }

  template class MonotoneMultigrid<2>;
  template class MonotoneMultigrid<3>;
} // namespace FoslsContact
