#include <fosls_contact/solvers/projected_gauss_seidel.h>

namespace FoslsContact
{
  void
  ProjectedGaussSeidel::solve(const ConstrainedQP &qp,
                              Vector<double> &     x,
                              Monitor &            monitor)
  {
    qp.project_to_feasible(x);
    monitor.start(x);
    const auto &   A = qp.matrix;
    Vector<double> x_old(x);
    for (;;)
      {
        x_old = x;
        for (types::global_dof_index i = 0; i < x.size(); ++i)
          {
            if (qp.role[i] == DoFRole::fixed)
              continue;
            const double a_ii = A.diag_element(i);
            if (a_ii <= 0)
              continue;
            double r = qp.rhs[i];
            for (auto e = A.begin(i); e != A.end(i); ++e)
              r -= e->value() * x[e->column()];
            double xi = x[i] + r / a_ii;
            if (qp.role[i] == DoFRole::bounded)
              xi = std::min(xi, qp.upper_bounds[i]);
            // the change of J along e_i, -r d + a_ii d^2 / 2, is <= 0 up to
            // round-off relative to its own terms (evaluating J itself
            // would compare numbers with far larger cancellation errors)
            const double d      = xi - x[i];
            const double change = -r * d + 0.5 * a_ii * d * d;
            if (change > 1e-10 * (std::abs(r * d) + 0.5 * a_ii * d * d) + 1e-300)
              monitor.note_energy_increase();
            x[i] = xi;
          }
        if (monitor.report(x, x_old))
          break;
      }
  }
} // namespace FoslsContact
