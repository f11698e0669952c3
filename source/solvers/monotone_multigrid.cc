#include <fosls_contact/solvers/active_set_direct.h>
#include <fosls_contact/solvers/box_qp.h>
#include <fosls_contact/solvers/coarse_obstacles.h>
#include <fosls_contact/solvers/monotone_multigrid.h>

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
    : hierarchy(discretization, transfer, finest_level)
    , parameters(parameters)
    , fine_sparsity(&fine_sparsity)
    , finest(finest_level)
    , smoother(finest_level + 1)
    , galerkin_sparsity(finest_level + 1)
    , product_sparsity(finest_level + 1)
    , prolongation_sparsity(finest_level + 1)
    , face_scale(finest_level + 1)
    , galerkin(finest_level + 1)
    , product(finest_level + 1)
    , truncated_prolongation(finest_level + 1)
    , galerkin_product(finest_level + 1)
    , scratch(finest_level + 1)
    , truncation_used(finest_level + 1)
    , version(finest_level + 1, 0)
    , version_used(finest_level + 1, numbers::invalid_unsigned_int)
    , reroute_used(finest_level + 1, false)
  {
    // The sparsity patterns of the truncated prolongations (P's pattern
    // plus, in the column of each coarse contact face, the DoFs coupled to
    // its sons, which the flux rerouting may use) and of their Galerkin
    // products; they hold every truncated product, so the solve only
    // recomputes values.
    for (unsigned int l = finest; l > 0; --l)
      {
        const SparsityPattern &A = l == finest ? fine_sparsity : galerkin_sparsity[l];
        const SparsityPattern &P0 = hierarchy.prolongation(l).get_sparsity_pattern();
        DynamicSparsityPattern prolongation_dsp(P0.n_rows(), P0.n_cols());
        for (auto e = P0.begin(); e != P0.end(); ++e)
          prolongation_dsp.add(e->row(), e->column());
        for (const auto &face : hierarchy.face_relations(l))
          for (const auto son : face.sons)
            for (auto e = A.begin(son); e != A.end(son); ++e)
              if (std::binary_search(face.inside.begin(), face.inside.end(), e->column()))
                prolongation_dsp.add(e->column(), face.coarse_dof);
        prolongation_sparsity[l].copy_from(prolongation_dsp);
        face_scale[l].assign(hierarchy.face_relations(l).size(), 1.);

        const SparsityPattern &P = prolongation_sparsity[l];
        DynamicSparsityPattern product_dsp, galerkin_dsp;
        product_dsp.compute_mmult_pattern(A, P);
        product_sparsity[l].copy_from(product_dsp);
        galerkin_dsp.compute_Tmmult_pattern(P, product_sparsity[l]);
        galerkin_sparsity[l - 1].copy_from(galerkin_dsp);
        truncated_prolongation[l].reinit(P);
        galerkin_product[l].initialize(P);
        product[l].reinit(product_sparsity[l]);
        galerkin[l - 1].reinit(galerkin_sparsity[l - 1]);
      }
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::update_coarse_operator(const unsigned int          l,
                                                 const SparseMatrix<double> &A,
                                                 const std::vector<DoFRole> &role,
                                                 const std::vector<bool> &   truncated,
                                                 const bool                  reroute)
  {
    // (truncation_used[l] is empty until the first product)
    if (truncated == truncation_used[l] && version[l] == version_used[l] &&
        reroute == reroute_used[l])
      return;
    const auto timing = section("Solve: Galerkin operators and patch setup");

    // P~: the rows of P at truncated DoFs are zero (its pattern holds P's
    // and the entries flux rerouting may add; both sorted by column)
    SparseMatrix<double> &      Pt = truncated_prolongation[l];
    const SparseMatrix<double> &P  = hierarchy.prolongation(l);
    parallel::apply_to_subranges(
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
    std::vector<bool> removed(P.n(), false);
    if (reroute)
      reroute_flux(l, A, role, truncated, removed);
    else
      {
        // a coarse face with a truncated son goes
        std::fill(face_scale[l].begin(), face_scale[l].end(), 1.);
        for (const auto &face : hierarchy.face_relations(l))
          for (const auto son : face.sons)
            if (truncated[son])
              removed[face.coarse_dof] = true;
      }
    if (std::find(removed.begin(), removed.end(), true) != removed.end())
      for (auto e = Pt.begin(); e != Pt.end(); ++e)
        if (removed[e->column()])
          e->value() = 0;

    galerkin_product[l].compute(A, Pt, product[l], galerkin[l - 1]);
    // the couplings of coarse functions whose fine couplings cancel (a
    // sixth of the product's nonzeros on the square) would lengthen the
    // patch residuals and couple patches that are not coupled
    zero_round_off(galerkin[l - 1], ConstrainedQP::round_off_drop);
    truncation_used[l] = truncated;
    version_used[l]    = version[l];
    reroute_used[l]    = reroute;
    ++version[l - 1];
    if (l - 1 > 0)
      smoother.initialize_level(l - 1,
                                galerkin[l - 1],
                                hierarchy.patches(l - 1),
                                hierarchy.patch_colors(l - 1),
                                hierarchy.level(l - 1).role);
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::reroute_flux(const unsigned int          l,
                                       const SparseMatrix<double> &A,
                                       const std::vector<DoFRole> &role,
                                       const std::vector<bool> &   truncated,
                                       std::vector<bool> &         removed)
  {
    SparseMatrix<double> &      Pt    = truncated_prolongation[l];
    const SparseMatrix<double> &P    = hierarchy.prolongation(l);
    const auto &                faces = hierarchy.face_relations(l);
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
            removed[j] = true;
            continue;
          }

        // d: the change of the column at the sons
        std::map<types::global_dof_index, double> d;
        for (const auto son : face.sons)
          d[son] = truncated[son] ? -P.el(son, j) : lost / free_sons.size();
        for (const auto son : free_sons)
          {
            Pt.add(son, j, d[son]);
            face_scale[l][k] = std::max(face_scale[l][k], Pt.el(son, j));
          }

        // the local correction e on the free, unbounded DoFs at the sons
        // inside the coarse cell (so that the column, and the Galerkin
        // operator, stay on the coupling pattern of the coarse cells; with
        // the DoFs on the cell's other faces too, 38 to 114 entries of the
        // coarse operators fell outside it on the square, with the same
        // iterations)
        std::vector<types::global_dof_index> local;
        for (const auto son : face.sons)
          for (auto e = A.begin(son); e != A.end(son); ++e)
            {
              const auto i = e->column();
              if (!truncated[i] && role[i] == DoFRole::free && d.count(i) == 0 &&
                  std::binary_search(face.inside.begin(), face.inside.end(), i) &&
                  std::find(local.begin(), local.end(), i) == local.end())
                local.push_back(i);
            }
        if (local.empty())
          continue;
        const unsigned int n = local.size();
        FullMatrix<double> A_local(n, n);
        Vector<double>     rhs(n), e(n);
        for (unsigned int a = 0; a < n; ++a)
          {
            for (unsigned int b = 0; b < n; ++b)
              A_local(a, b) = A.el(local[a], local[b]);
            for (const auto &[son, value] : d)
              rhs[a] -= A.el(local[a], son) * value;
          }
        // gauss_jordan pivots (FullMatrix::invert uses cofactor formulas for
        // n <= 4, see BoxQP)
        A_local.gauss_jordan();
        A_local.vmult(e, rhs);
        for (unsigned int a = 0; a < n; ++a)
          Pt.add(local[a], j, e[a]);
      }
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::coarse_solve(const SparseMatrix<double> &A,
                                       const Vector<double> &      r,
                                       const Vector<double> &      ub,
                                       const std::vector<DoFRole> &role,
                                       Vector<double> &            v)
  {
    const auto timing = section("Solve: coarse solve");
    if (&A != coarse_matrix || version[0] != coarse_version)
      {
        // factorize once per coarse operator: it changes only with the
        // truncation, while the W-cycles of a Newton step visit it
        // hundreds of times (measured on the half disc, 4 levels: 1700
        // coarse solves, 31 ms each when factorized every time)
        coarse_matrix  = &A;
        coarse_version = version[0];
        coarse_dofs.clear();
        for (types::global_dof_index i = 0; i < v.size(); ++i)
          if (role[i] != DoFRole::fixed && A.diag_element(i) > 0)
            coarse_dofs.push_back(i);
        if (coarse_dofs.size() <= 2000)
          {
            const unsigned int n = coarse_dofs.size();
            FullMatrix<double> M(n, n);
            for (unsigned int a = 0; a < n; ++a)
              for (auto e = A.begin(coarse_dofs[a]); e != A.end(coarse_dofs[a]); ++e)
                {
                  const auto b = std::lower_bound(coarse_dofs.begin(), coarse_dofs.end(), e->column());
                  if (b != coarse_dofs.end() && *b == e->column())
                    M(a, b - coarse_dofs.begin()) = e->value();
                }
            coarse_qp = BoxQP(M);
          }
      }
    const auto &       dofs = coarse_dofs;
    const unsigned int n    = dofs.size();
    if (n == 0)
      return;
    if (n <= 2000)
      {
        Vector<double>     g(n), s(n), c;
        std::vector<bool>  at_bound;
        Vector<double>     Av(v.size());
        A.vmult(Av, v);
        for (unsigned int a = 0; a < n; ++a)
          {
            g[a] = r[dofs[a]] - Av[dofs[a]];
            s[a] = role[dofs[a]] == DoFRole::bounded ?
                     std::max(0., ub[dofs[a]] - v[dofs[a]]) :
                     std::numeric_limits<double>::infinity();
          }
        coarse_qp.solve(g, s, c, at_bound);
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
                                Vector<double> &            v,
                                const bool                  linear)
  {
    if (l == 0)
      {
        coarse_solve(A, r, ub, role, v);
        return;
      }

    // the finest level of the linear cycle relaxes with the linear roles
    // (on coarser levels the truncation takes care of them)
    smoother.use_linear_roles(l, linear && l == finest);
    smoother.set_obstacles(l, ub);
    smoother.set_backward(false);
    smoother.set_steps(parameters.pre_smoothing);
    {
      const auto timing = section("Solve: smoothing");
      smoother.smooth(l, v, r);
    }

    const double       inf         = std::numeric_limits<double>::infinity();
    const auto &       coarse_role = hierarchy.level(l - 1).role;
    const unsigned int visits      = (l == 1 ? 1 : parameters.cycle_gamma);
    const auto         n           = v.size();
    // the work vectors of this level (a level is never visited twice at
    // once, and allocating them per visit showed up as page faults)
    Scratch &          work        = scratch[l];
    auto &             defect      = work.defect;
    if (work.residual.size() != n)
      {
        const auto n_coarse = hierarchy.level(l - 1).n_dofs;
        work.truncated.resize(n);
        work.defect.reinit(n);
        work.residual.reinit(n);
        work.w.reinit(n);
        work.r_coarse.reinit(n_coarse);
        work.ub_coarse.reinit(n_coarse);
        work.c.reinit(n_coarse);
        work.Ac.reinit(n_coarse);
      }
    if (work.operator_version != operator_version(l, A) || work.role != role)
      {
        // The part of the truncation that does not depend on the iterate:
        // fixed DoFs, and DoFs whose diagonal is zero, switched off by the
        // truncation of the finer level. It changes only with the
        // operator (which changes only with that truncation) or the roles
        // (those of the Newton step's linear problem), so a visit only
        // looks at the bounded DoFs.
        work.fixed_truncated.resize(n);
        work.bounded.clear();
        defect = std::numeric_limits<double>::infinity();
        for (types::global_dof_index i = 0; i < n; ++i)
          {
            work.fixed_truncated[i] = role[i] == DoFRole::fixed || A.diag_element(i) <= 0;
            if (role[i] == DoFRole::bounded && !work.fixed_truncated[i])
              work.bounded.push_back(i);
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

    for (unsigned int visit = 0; visit < visits; ++visit)
      {
        // Truncation (eq. 34): fixed, active and switched-off DoFs do not
        // move; their defect obstacle is +inf (eqs. 35-36).
        truncated = work.fixed_truncated;
        for (const auto i : work.bounded)
          {
            truncated[i] = v[i] >= ub[i]; // active
            defect[i]    = truncated[i] ? inf : ub[i] - v[i];
          }
        update_coarse_operator(l, A, role, truncated, !linear);
        const auto &P = truncated_prolongation[l];

        A.vmult(residual, v);
        residual.sadd(-1., 1., r);
        galerkin_product[l].Tvmult(r_coarse, residual);
        CoarseObstacles::project(parameters.projection,
                                 hierarchy.vertex_relations(l),
                                 hierarchy.face_relations(l),
                                 face_scale[l],
                                 defect,
                                 ub_coarse);
        c = 0;
        cycle(l - 1, galerkin[l - 1], r_coarse, ub_coarse, coarse_role, c, linear);

        P.vmult(w, c);
        // keep the iterate feasible (a no-op when K_H is inside K_h)
        double alpha = 1.;
        for (const auto i : work.bounded)
          if (!truncated[i] && w[i] > 0 && v[i] + w[i] > ub[i])
            alpha = std::min(alpha, std::max(0., (ub[i] - v[i]) / w[i]));
        if (alpha < 1.)
          ++n_dampings;

        // the change of Q_l: -alpha w.residual + alpha^2/2 w.A w, with
        // w = P~ c: w.residual = c.r_coarse and w.A w = c.A_{l-1} c (the
        // Galerkin product), on the coarse level instead of a product with
        // the fine matrix
        galerkin[l - 1].vmult(Ac, c);
        const double wr = c * r_coarse, wAw = c * Ac;
        const double change = -alpha * wr + 0.5 * alpha * alpha * wAw;
        if (change > 1e-10 * (std::abs(alpha * wr) + 0.5 * alpha * alpha * std::abs(wAw)) + 1e-300)
          ++n_increases;
        v.add(alpha, w);
        for (const auto i : work.bounded)
          if (v[i] > ub[i])
            v[i] = ub[i]; // round-off of the damped step only
      }

    smoother.use_linear_roles(l, linear && l == finest);
    smoother.set_obstacles(l, ub);
    smoother.set_backward(true);
    smoother.set_steps(parameters.post_smoothing);
    {
      const auto timing = section("Solve: smoothing");
      smoother.smooth(l, v, r);
    }
    smoother.use_linear_roles(l, false);
  }


  namespace
  {
    /** A restricted to the inactive set: the rows and columns of the
     * fixed DoFs are 0. */
    struct TruncatedOperator
    {
      const SparseMatrix<double> &                A;
      const std::vector<types::global_dof_index> &fixed;
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        A.vmult(dst, src);
        // take out the columns of fixed DoFs (in CG they are zero anyway:
        // the preconditioner never moves them); A is symmetric, so column
        // i is row i
        for (const auto i : fixed)
          if (src[i] != 0.)
            for (auto e = A.begin(i); e != A.end(i); ++e)
              dst[e->column()] -= e->value() * src[i];
        for (const auto i : fixed)
          dst[i] = 0;
      }
    };

    /** The linear truncated cycle as a preconditioner. */
    template <typename Cycle>
    struct CyclePreconditioner
    {
      Cycle cycle;
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        dst = 0;
        cycle(src, dst);
      }
    };
  } // namespace


  template <int dim>
  unsigned int
  MonotoneMultigrid<dim>::newton_step(const ConstrainedQP &qp, Vector<double> &x)
  {
    unsigned int n_cycles = 0;
    const auto &A = qp.matrix;
    const auto  n = x.size();

    smoother.set_obstacles(finest, qp.upper_bounds);
    smoother.set_backward(false);
    smoother.set_steps(parameters.pre_smoothing);
    {
      const auto timing = section("Solve: smoothing");
      smoother.smooth(finest, x, qp.rhs);
    }

    // The linear problem keeps a DoF at its bound only where the bound
    // holds it: the multiplier mu_i = (b - A x)_i is positive. A DoF that
    // sits at its bound while the gradient pulls it inside (mu_i < 0) is
    // left free, so that the Newton direction can release it.
    Vector<double> residual(n), d(n), increment(n), rhs(n), Ae(n);
    A.vmult(residual, x);
    residual.sadd(-1., 1., qp.rhs);
    linear_role = qp.role;
    for (types::global_dof_index i = 0; i < n; ++i)
      if (qp.role[i] == DoFRole::bounded)
        linear_role[i] = (x[i] >= qp.upper_bounds[i] && residual[i] >= 0) ?
                           DoFRole::fixed :
                           DoFRole::free;

    Vector<double> infinite(n);
    infinite = std::numeric_limits<double>::infinity();
    auto apply_cycle = [&](const Vector<double> &r, Vector<double> &v) {
      cycle(finest, A, r, infinite, linear_role, v, true);
      ++n_cycles;
    };
    CyclePreconditioner<decltype(apply_cycle)> preconditioner{apply_cycle};
    std::vector<types::global_dof_index> fixed;
    for (types::global_dof_index i = 0; i < n; ++i)
      if (linear_role[i] == DoFRole::fixed)
        fixed.push_back(i);
    TruncatedOperator op{A, fixed};

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
    for (unsigned int round = 0; round < max_rounds + 1; ++round)
      {
        if (linear_role != linear_role_used)
          {
            const auto timing = section("Solve: Galerkin operators and patch setup");
            smoother.set_linear_roles(finest, linear_role);
            linear_role_used = linear_role;
          }
        rhs = residual;
        if (round > 0) // the increment is zero until a DoF was moved to its bound
          {
            A.vmult(Ae, increment);
            rhs -= Ae;
          }
        for (types::global_dof_index i = 0; i < n; ++i)
          if (linear_role[i] == DoFRole::fixed)
            rhs[i] = 0;
        SolverControl control(parameters.krylov_steps, 1e-3 * rhs.l2_norm(), false, false);
        SolverCG<Vector<double>> cg(control);
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
        for (types::global_dof_index i = 0; round < max_rounds && i < n; ++i)
          if (qp.role[i] == DoFRole::bounded && linear_role[i] == DoFRole::free &&
              x[i] + d[i] > qp.upper_bounds[i])
            {
              linear_role[i] = DoFRole::fixed;
              fixed.push_back(i);
              increment[i]   = qp.upper_bounds[i] - x[i];
              violated       = true;
            }
        if (!violated)
          break;
      }

    // Line search along the projected Newton step: p = P_K(x + alpha d),
    // alpha the minimizer along d. Every point of the segment [x, p] is
    // feasible (K is convex) and J is a quadratic on it, so its minimizer
    // t in (0, 1] is taken: J decreases whenever p - x is a descent
    // direction. Otherwise the feasible part of the step along d is taken,
    // which decreases J by convexity.
    Vector<double> Ad(n), step(n);
    A.vmult(Ad, d);
    const double dAd = d * Ad, dr = d * residual;
    if (!(dAd > 0) || !(dr > 0))
      return n_cycles;
    step = x;
    step.add(dr / dAd, d);
    qp.project_to_feasible(step);
    step -= x;
    Vector<double> As(n);
    A.vmult(As, step);
    const double sAs = step * As, sr = step * residual;
    if (sAs > 0 && sr > 0)
      x.add(std::min(1., sr / sAs), step);
    else
      {
        double t = dr / dAd;
        for (types::global_dof_index i = 0; i < n; ++i)
          if (qp.role[i] == DoFRole::bounded && d[i] > 0)
            t = std::min(t, std::max(0., (qp.upper_bounds[i] - x[i]) / d[i]));
        x.add(t, d);
      }
    qp.project_to_feasible(x); // round-off only

    smoother.set_obstacles(finest, qp.upper_bounds);
    smoother.set_backward(true);
    smoother.set_steps(parameters.post_smoothing);
    {
      const auto timing = section("Solve: smoothing");
      smoother.smooth(finest, x, qp.rhs);
    }
    return n_cycles;
  }


  template <int dim>
  void
  MonotoneMultigrid<dim>::solve(const ConstrainedQP &qp,
                                Vector<double> &     x,
                                Monitor &            monitor)
  {
    AssertThrow(qp.size() == hierarchy.level(finest).n_dofs,
                ExcMessage("monotone multigrid: problem and hierarchy differ"));
    AssertThrow(&qp.matrix.get_sparsity_pattern() == fine_sparsity &&
                  fine_sparsity->n_nonzero_elements() == qp.matrix.n_nonzero_elements(),
                ExcMessage("monotone multigrid: the problem's matrix is not on the "
                           "pattern the solver was set up for"));
    qp.project_to_feasible(x);
    monitor.start(x);
    smoother.initialize_level(finest,
                              qp.matrix,
                              hierarchy.patches(finest),
                              hierarchy.patch_colors(finest),
                              qp.role);
    linear_role_used.clear(); // the linear roles of the finest level are gone
    ++version[finest];

    Vector<double> x_old(x);
    for (;;)
      {
        x_old = x;
        const unsigned int increases_before = n_increases + smoother.energy_increases();
        const unsigned int dampings_before  = n_dampings;
        if (finest == 0)
          {
            // one level: the exact coarse solve is the whole method
            coarse_solve(qp.matrix, qp.rhs, qp.upper_bounds, qp.role, x);
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

  template <int dim>
  std::vector<unsigned int>
  MonotoneMultigrid<dim>::n_patch_colors() const
  {
    std::vector<unsigned int> n;
    for (unsigned int l = 1; l <= finest; ++l)
      {
        const auto &colors = hierarchy.patch_colors(l);
        n.push_back(colors.empty() ? 0 : *std::max_element(colors.begin(), colors.end()) + 1);
      }
    return n;
  }


  template class MonotoneMultigrid<2>;
  template class MonotoneMultigrid<3>;
} // namespace FoslsContact
