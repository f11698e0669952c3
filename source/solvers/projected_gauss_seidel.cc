#include <fosls_contact/qp/gathered_qp.h>
#include <fosls_contact/qp/tangential_pair.h>
#include <fosls_contact/solvers/energy_check.h>
#include <fosls_contact/solvers/projected_gauss_seidel.h>

namespace FoslsContact
{
  namespace
  {
    /** r_i = (b - A x)_i. */
    double
    row_residual(const ConstrainedQP &qp, const LevelVector &x, const types::global_dof_index i)
    {
      double r = qp.rhs.local_element(i);
      for (auto e = qp.matrix.begin(i); e != qp.matrix.end(i); ++e)
        r -= e->value() * x.local_element(e->column());
      return r;
    }


    /**
     * The 2x2 block of a 3D friction pair (i, j) (FrictionTerms::partner)
     * relaxed together: its exact minimizer with the other entries fixed,
     * in the disc of the slip bound (tractions) or with the Euclidean norm
     * of the slip (TangentialPair). Returns whether J increased.
     */
    bool
    relax_pair(const ConstrainedQP &qp, const types::global_dof_index i, LevelVector &x)
    {
      using namespace TangentialPair;
      const types::global_dof_index j = qp.friction.partner_of(i);
      const Matrix2 H{qp.matrix.diag_element(i), qp.matrix.el(i, j), qp.matrix.diag_element(j)};
      const Vector2 r{row_residual(qp, x, i), row_residual(qp, x, j)};
      const Vector2 old{x.local_element(i), x.local_element(j)};
      Vector2       next;
      double        friction_change = 0, friction_size = 0;
      if (qp.role[i] == DoFRole::slip)
        {
          // y = x - p: 1/2 y^T H y - (r + H z0)^T y + w |y| up to a constant
          const Vector2 p{qp.friction.slip_references.local_element(i),
                          qp.friction.slip_references.local_element(j)};
          const Vector2 z0{old[0] - p[0], old[1] - p[1]};
          const double  w = qp.friction.slip_weights.local_element(i);
          const Vector2 y = minimize_with_norm(
            H, {r[0] + H[0] * z0[0] + H[1] * z0[1], r[1] + H[1] * z0[0] + H[2] * z0[1]}, w);
          next            = {p[0] + y[0], p[1] + y[1]};
          friction_change = w * (norm(y) - norm(z0));
          friction_size   = w * (norm(y) + norm(z0));
        }
      else
        next = minimize_in_disc(H,
                                {r[0] + H[0] * old[0] + H[1] * old[1],
                                 r[1] + H[1] * old[0] + H[2] * old[1]},
                                qp.friction.traction_bounds.local_element(i));
      const Vector2 d{next[0] - old[0], next[1] - old[1]};
      const double  quadratic = 0.5 * (H[0] * d[0] * d[0] + 2 * H[1] * d[0] * d[1] + H[2] * d[1] * d[1]);
      const double  change    = -r[0] * d[0] - r[1] * d[1] + quadratic + friction_change;
      x.local_element(i)      = next[0];
      x.local_element(j)      = next[1];
      return increases_energy(change,
                              std::abs(r[0] * d[0]) + std::abs(r[1] * d[1]) + quadratic + friction_size);
    }
  } // namespace


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
                if (qp.has_friction() && qp.friction.partner_of(i) != FrictionTerms::no_partner)
                  {
                    if (relax_pair(qp, i, whole))
                      ++increases;
                    continue;
                  }
                double r = qp.rhs.local_element(i);
                for (auto e = A.begin(i); e != A.end(i); ++e)
                  r -= e->value() * whole.local_element(e->column());
                const double x_old_i = whole.local_element(i);
                double       xi      = x_old_i + r / a_ii;
                // the friction term's change along e_i (a slip DoF: the
                // minimizer of a_ii d^2 / 2 - r d + w |x_i + d - p_i| is
                // the unconstrained one moved toward p_i by w / a_ii, or p_i)
                double friction_change = 0, friction_size = 0;
                if (qp.role[i] == DoFRole::bounded)
                  xi = std::min(xi, qp.upper_bounds.local_element(i));
                // (a problem without friction terms whose roles have them,
                // a level of nested iteration: those DoFs are free)
                else if (qp.role[i] == DoFRole::traction && qp.has_friction())
                  {
                    const double s = qp.friction.traction_bounds.local_element(i);
                    xi             = std::max(-s, std::min(xi, s));
                  }
                else if (qp.role[i] == DoFRole::slip && qp.has_friction())
                  {
                    const double w = qp.friction.slip_weights.local_element(i);
                    const double p = qp.friction.slip_references.local_element(i);
                    const double z = xi - p, shrink = w / a_ii;
                    xi             = z > shrink ? xi - shrink : z < -shrink ? xi + shrink : p;
                    friction_change = w * (std::abs(xi - p) - std::abs(x_old_i - p));
                    friction_size   = w * (std::abs(xi - p) + std::abs(x_old_i - p));
                  }
                // the change of J along e_i, -r d + a_ii d^2 / 2 (plus the
                // friction term's), is <= 0 up to round-off relative to its
                // own terms (evaluating J itself would compare numbers with
                // far larger cancellation errors)
                const double d      = xi - x_old_i;
                const double change = -r * d + 0.5 * a_ii * d * d + friction_change;
                if (increases_energy(change, std::abs(r * d) + 0.5 * a_ii * d * d + friction_size))
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
