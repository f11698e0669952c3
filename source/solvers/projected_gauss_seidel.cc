#include <fosls_contact/qp/gathered_qp.h>
#include <fosls_contact/solvers/energy_check.h>
#include <fosls_contact/solvers/projected_gauss_seidel.h>

namespace FoslsContact
{
  void
  ProjectedGaussSeidel::solve(const ConstrainedQP &distributed,
                              LevelVector &        x,
                              IterationObserver &  observer)
  {
    update_ghosts(x);
    distributed.project_to_feasible(x);
    observer.enable_divergence_detection();
    observer.start(x);
    // The sweep is sequential in the order of the support points: it runs
    // on the first process, on the gathered problem (the baseline, meant
    // for one process).
    const GatheredQP gathered(distributed);
    AssertThrow(!gathered.here() || order.size() == distributed.size(),
                ExcMessage("projected Gauss-Seidel: the sweep order does not fit the problem"));
    LevelVector      whole = gathered.gather(x), x_old(x);
    const MPI_Comm   comm  = distributed.get_communicator();
    for (;;)
      {
        x_old                  = x;
        unsigned int increases = 0;
        if (gathered.here())
          {
            const auto &qp = gathered.qp();
            const auto &A  = qp.matrix;
            for (const types::global_dof_index i : order)
              {
                if (qp.role[i] == DoFRole::fixed)
                  continue;
                const double a_ii = A.diag_element(i);
                if (a_ii <= 0)
                  continue;
                double r = qp.rhs.local_element(i);
                for (auto e = A.begin(i); e != A.end(i); ++e)
                  r -= e->value() * whole.local_element(e->column());
                double xi = whole.local_element(i) + r / a_ii;
                if (qp.role[i] == DoFRole::bounded)
                  xi = std::min(xi, qp.upper_bounds.local_element(i));
                // the change of J along e_i, -r d + a_ii d^2 / 2, is <= 0 up
                // to round-off relative to its own terms (evaluating J
                // itself would compare numbers with far larger cancellation
                // errors)
                const double d      = xi - whole.local_element(i);
                const double change = -r * d + 0.5 * a_ii * d * d;
                if (increases_energy(change, std::abs(r * d) + 0.5 * a_ii * d * d))
                  ++increases;
                whole.local_element(i) = xi;
              }
          }
        gathered.scatter(whole, x);
        observer.note_energy_increases(Utilities::MPI::sum(increases, comm));
        if (observer.report(x, x_old))
          break;
      }
  }
} // namespace FoslsContact
