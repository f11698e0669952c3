#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/box_qp.h>
#include <fosls_contact/solvers/coarse_obstacles.h>
#include <fosls_contact/solvers/monotone_multigrid.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  template <int dim>
  MonotoneMultigrid<dim>::MonotoneMultigrid(const Discretization<dim> &discretization,
                                            const LevelTransfer<dim> & transfer,
                                            const unsigned int         finest_level,
                                            const Parameters::Solver & parameters)
    : hierarchy(discretization, transfer, finest_level)
    , parameters(parameters)
    , finest(finest_level)
    , smoother(finest_level + 1)
    , galerkin_sparsity(finest_level + 1)
    , product_sparsity(finest_level + 1)
    , galerkin(finest_level + 1)
    , product(finest_level + 1)
    , truncated_prolongation(finest_level + 1)
    , truncation_used(finest_level + 1)
    , version(finest_level + 1, 0)
    , version_used(finest_level + 1, numbers::invalid_unsigned_int)
    , built(finest_level + 1, false)
  {}


  template <int dim>
  void
  MonotoneMultigrid<dim>::update_coarse_operator(const unsigned int          l,
                                                 const SparseMatrix<double> &A,
                                                 const std::vector<bool> &   truncated)
  {
    if (built[l] && truncated == truncation_used[l] && version[l] == version_used[l])
      return;

    const SparseMatrix<double> &P = hierarchy.prolongation(l);
    if (!built[l])
      {
        truncated_prolongation[l].reinit(P.get_sparsity_pattern());
        // first product: build the sparsity patterns of the untruncated
        // product, which then hold every truncated product as well
        product_sparsity[l].reinit(0, 0, 0);
        product_sparsity[l].compress();
        product[l].reinit(product_sparsity[l]);
        galerkin_sparsity[l - 1].reinit(0, 0, 0);
        galerkin_sparsity[l - 1].compress();
        galerkin[l - 1].reinit(galerkin_sparsity[l - 1]);
      }
    truncated_prolongation[l].copy_from(P);
    for (types::global_dof_index i = 0; i < truncated.size(); ++i)
      if (truncated[i])
        for (auto e = truncated_prolongation[l].begin(i);
             e != truncated_prolongation[l].end(i);
             ++e)
          e->value() = 0;

    A.mmult(product[l], truncated_prolongation[l], Vector<double>(), !built[l]);
    truncated_prolongation[l].Tmmult(galerkin[l - 1],
                                     product[l],
                                     Vector<double>(),
                                     !built[l]);
    built[l]           = true;
    truncation_used[l] = truncated;
    version_used[l]    = version[l];
    ++version[l - 1];
    if (l - 1 > 0)
      smoother.initialize_level(l - 1,
                                galerkin[l - 1],
                                hierarchy.patches(l - 1),
                                hierarchy.level(l - 1).role);
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::coarse_solve(const SparseMatrix<double> &A,
                                       const Vector<double> &      r,
                                       const Vector<double> &      ub,
                                       const std::vector<DoFRole> &role,
                                       Vector<double> &            v)
  {
    std::vector<types::global_dof_index> dofs;
    for (types::global_dof_index i = 0; i < v.size(); ++i)
      if (role[i] != DoFRole::fixed && A.diag_element(i) > 0)
        dofs.push_back(i);
    const unsigned int n = dofs.size();
    if (n == 0)
      return;
    if (n <= 2000)
      {
        FullMatrix<double> M(n, n);
        Vector<double>     g(n), s(n), c;
        std::vector<bool>  at_bound;
        Vector<double>     Av(v.size());
        A.vmult(Av, v);
        for (unsigned int a = 0; a < n; ++a)
          {
            for (unsigned int b = 0; b < n; ++b)
              M(a, b) = A.el(dofs[a], dofs[b]);
            g[a] = r[dofs[a]] - Av[dofs[a]];
            s[a] = role[dofs[a]] == DoFRole::bounded ?
                     std::max(0., ub[dofs[a]] - v[dofs[a]]) :
                     std::numeric_limits<double>::infinity();
          }
        BoxQP(M).solve(g, s, c, at_bound);
        for (unsigned int a = 0; a < n; ++a)
          v[dofs[a]] = at_bound[a] ? ub[dofs[a]] : v[dofs[a]] + c[a];
      }
    else
      {
        // a large coarse mesh: the sparse primal-dual active set method
        ActiveSetDirect::solve_quietly(A, r, role, ub, v, 100);
      }
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::cycle(const unsigned int          l,
                                const SparseMatrix<double> &A,
                                const Vector<double> &      r,
                                const Vector<double> &      ub,
                                const std::vector<DoFRole> &role,
                                Vector<double> &            v)
  {
    if (l == 0)
      {
        coarse_solve(A, r, ub, role, v);
        return;
      }

    smoother.set_obstacles(l, ub);
    smoother.set_backward(false);
    smoother.set_steps(parameters.pre_smoothing);
    smoother.smooth(l, v, r);

    const double       inf     = std::numeric_limits<double>::infinity();
    const auto &       coarse_role = hierarchy.level(l - 1).role;
    const unsigned int visits  = (l == 1 ? 1 : parameters.cycle_gamma);
    const auto         n       = v.size();
    std::vector<bool>  truncated(n);
    Vector<double>     defect(n), residual(n), w(n), Aw(n);
    Vector<double>     r_coarse(hierarchy.level(l - 1).n_dofs),
      ub_coarse(hierarchy.level(l - 1).n_dofs), c(hierarchy.level(l - 1).n_dofs);

    for (unsigned int visit = 0; visit < visits; ++visit)
      {
        // Truncation (eq. 34): fixed, active and switched-off DoFs do not
        // move; their defect obstacle is +inf (eqs. 35-36).
        for (types::global_dof_index i = 0; i < n; ++i)
          {
            const bool active = role[i] == DoFRole::bounded && v[i] >= ub[i];
            truncated[i] = role[i] == DoFRole::fixed || active ||
                           A.diag_element(i) <= 0;
            defect[i] = (role[i] == DoFRole::bounded && !truncated[i]) ?
                          ub[i] - v[i] :
                          inf;
          }
        update_coarse_operator(l, A, truncated);
        const auto &P = truncated_prolongation[l];

        A.vmult(residual, v);
        residual.sadd(-1., 1., r);
        P.Tvmult(r_coarse, residual);
        CoarseObstacles::project(parameters.projection,
                                 hierarchy.vertex_relations(l),
                                 hierarchy.face_relations(l),
                                 defect,
                                 ub_coarse);
        c = 0;
        cycle(l - 1, galerkin[l - 1], r_coarse, ub_coarse, coarse_role, c);

        P.vmult(w, c);
        // keep the iterate feasible (a no-op when K_H is inside K_h)
        double alpha = 1.;
        for (types::global_dof_index i = 0; i < n; ++i)
          if (role[i] == DoFRole::bounded && !truncated[i] && w[i] > 0 &&
              v[i] + w[i] > ub[i])
            alpha = std::min(alpha, std::max(0., (ub[i] - v[i]) / w[i]));
        if (alpha < 1.)
          ++n_dampings;

        // the change of Q_l: -alpha w.residual + alpha^2/2 w.A w
        A.vmult(Aw, w);
        const double wr = w * residual, wAw = w * Aw;
        const double change = -alpha * wr + 0.5 * alpha * alpha * wAw;
        if (change > 1e-10 * (std::abs(alpha * wr) + 0.5 * alpha * alpha * std::abs(wAw)) + 1e-300)
          ++n_increases;
        v.add(alpha, w);
        for (types::global_dof_index i = 0; i < n; ++i)
          if (role[i] == DoFRole::bounded && v[i] > ub[i])
            v[i] = ub[i]; // round-off of the damped step only
      }

    smoother.set_obstacles(l, ub);
    smoother.set_backward(true);
    smoother.set_steps(parameters.post_smoothing);
    smoother.smooth(l, v, r);
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::solve(const ConstrainedQP &qp,
                                Vector<double> &     x,
                                Monitor &            monitor)
  {
    AssertThrow(qp.size() == hierarchy.level(finest).n_dofs,
                ExcMessage("monotone multigrid: problem and hierarchy differ"));
    qp.project_to_feasible(x);
    monitor.start(x);
    smoother.initialize_level(finest, qp.matrix, hierarchy.patches(finest), qp.role);
    ++version[finest];

    Vector<double> x_old(x);
    for (;;)
      {
        x_old = x;
        const unsigned int increases_before = n_increases + smoother.energy_increases();
        const unsigned int dampings_before  = n_dampings;
        if (finest == 0)
          coarse_solve(qp.matrix, qp.rhs, qp.upper_bounds, qp.role, x);
        else
          cycle(finest, qp.matrix, qp.rhs, qp.upper_bounds, qp.role, x);
        for (unsigned int k = increases_before;
             k < n_increases + smoother.energy_increases();
             ++k)
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
