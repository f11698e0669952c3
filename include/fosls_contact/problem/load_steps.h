#ifndef fosls_contact_problem_load_steps_h
#define fosls_contact_problem_load_steps_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <fosls_contact/output/contact_table.h>

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * The table of a load path (Data/Load steps), one row per step, in the
   * scene's units: what an engineer reads off a test machine at every
   * step, written to summary.json ("load_steps") and load_steps.csv.
   *
   * The contact force F is split along the contact pressure's mean
   * direction: n = the sum over the contact vertices of their share of
   * the boundary times their pressure times the obstacle normal there,
   * normalized (the obstacle normal itself on a flat obstacle). The
   * normal force is -F.n (positive where the obstacle pushes the body),
   * the tangential force |F - (F.n) n|: 0 up to round-off without
   * friction on a flat obstacle, where the tangential traction is
   * prescribed 0 on every contact face.
   */
  template <int dim>
  class LoadSteps
  {
  public:
    struct Step
    {
      /**
       * The step's files: their time in solution.pvd and the N of
       * solution_000N and contact_000N.csv (the step's index, after the
       * meshes of an adaptive first step).
       */
      unsigned int                  output_index = 0;
      /** The values of the constants the load path changes. */
      std::map<std::string, double> constants;
      unsigned int                  iterations = 0, cycles = 0;
      /**
       * The residual reduction per linear cycle of the step's Newton
       * steps (SolverStatistics::Multilevel::linear_rate()), NaN without.
       */
      double                        linear_rate = std::numeric_limits<double>::quiet_NaN();
      /**
       * The corrections' reduction per iteration (Newton step or cycle)
       * of the step's solves, over all its Tresca problems: the geometric
       * mean of the iterations above the round-off floor
       * (Monitor::measured_reduction()), NaN if none is.
       */
      double                        iteration_rate = std::numeric_limits<double>::quiet_NaN();
      bool                          converged = false;
      double                        functional = 0;
      Tensor<1, dim>                force;
      double                        normal_force = 0, tangential_force = 0;
      /** The contact zone (ContactZone): width or area, peak pressure. */
      double                        contact_measure = 0, peak_pressure = 0;
      unsigned int                  vertices_in_contact = 0;
      /**
       * With friction: the contact vertices that stick and that slip in
       * the step (ContactRow::status), columns of the table only then.
       */
      bool                          friction = false;
      unsigned int                  stick_vertices = 0, slip_vertices = 0;
      /** The force on the body at each Dirichlet boundary id (the reaction). */
      std::map<types::boundary_id, Tensor<1, dim>> reactions;
    };

    /**
     * The normal and tangential force of @p step from its contact force
     * and the contact table @p rows (on the first process; the others
     * leave both 0), with the obstacle normal @p normal at a position
     * in the scene's units.
     */
    /**
     * The numbers of stick and slip vertices of the contact table @p rows
     * with its friction columns (ContactRow::status).
     */
    static std::pair<unsigned int, unsigned int>
    count_status(const std::vector<typename ContactRow<dim>::Values> &rows);

    template <typename Normal>
    static void split_force(Step &                                               step,
                            const std::vector<typename ContactRow<dim>::Values> &rows,
                            const Normal &                                       normal);

    /**
     * The row of step @p index: a new last row, or the last row again (the
     * first step of a load path on each mesh of its adaptive loop).
     */
    void set(const unsigned int index, const Step &step)
    {
      Assert(index == steps.size() || index + 1 == steps.size(), ExcInternalError());
      if (index == steps.size())
        steps.push_back(step);
      else
        steps.back() = step;
    }
    unsigned int size() const { return steps.size(); }
    const Step &back() const { return steps.back(); }

    /** summary.json's "load_steps": a list of one object per step. */
    std::string json() const;
    /** load_steps.csv: a header and one row per step. */
    std::string csv() const;

  private:
    std::vector<Step> steps;
  };


  template <int dim>
  template <typename Normal>
  void
  LoadSteps<dim>::split_force(Step &                                               step,
                              const std::vector<typename ContactRow<dim>::Values> &rows,
                              const Normal &                                       normal)
  {
    using Row = ContactRow<dim>;
    Tensor<1, dim> direction;
    for (const auto &row : rows)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = row[Row::x + d];
        direction += row[Row::share] * std::max(0., -row[Row::sigma_nn]) * normal(x);
      }
    if (direction.norm() == 0.)
      return;
    direction /= direction.norm();
    const double along    = step.force * direction;
    step.normal_force     = -along;
    step.tangential_force = (step.force - along * direction).norm();
  }
} // namespace FoslsContact

#endif
