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
        const double J_old = qp.value(x);
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
            x[i] = xi;
          }
        if (qp.value(x) > J_old + 1e-13 * std::abs(J_old))
          monitor.note_energy_increase();
        if (monitor.report(x, x_old))
          break;
      }
  }
} // namespace FoslsContact
