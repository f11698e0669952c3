#ifndef fosls_contact_output_postprocessor_h
#define fosls_contact_output_postprocessor_h

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/output/output_directory.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/physical_mapping.h>
#include <fosls_contact/scene/reference_scales.h>
#include <fosls_contact/solvers/monitor.h>

#include <map>
#include <string>
#include <vector>

namespace FoslsContact
{
  /** Error norms against the exact solution of a manufactured scene. */
  struct ErrorNorms
  {
    double u_l2 = 0, u_h1_semi = 0, sigma_l2 = 0, sigma_div = 0;
    double u_h1() const { return std::sqrt(u_l2 * u_l2 + u_h1_semi * u_h1_semi); }
    double sigma_hdiv() const
    {
      return std::sqrt(sigma_l2 * sigma_l2 + sigma_div * sigma_div);
    }
    /**
     * sqrt(|u|_H1^2 + |sigma|_Hdiv^2) of the dimensionless problem (u/L
     * and sigma/S on the domain x/L, doc/method.md section 1) for norms
     * computed in the scene's units: the norm in which the least-squares
     * functional J^ bounds the error from above and below, and the same
     * number in every unit system, so that sqrt(J^) over it is a relative
     * error and an efficiency index is dimensionless.
     */
    double scaled(const ReferenceScales &scaling, const unsigned int dim) const
    {
      const double L = scaling.length, S = scaling.stress;
      return std::sqrt((u_l2 * u_l2 / (L * L) + u_h1_semi * u_h1_semi +
                        (sigma_l2 * sigma_l2 + sigma_div * sigma_div * L * L) / (S * S)) /
                       std::pow(L, double(dim)));
    }
  };

  /** Extremes of the fields, in the scene's units. */
  struct FieldMaxima
  {
    double displacement = 0; ///< max |u|
    double von_mises    = 0; ///< max of the von Mises stress (StressMeasures)
    /**
     * Where the von Mises stress takes its maximum (x, y[, z]; the first
     * such cell corner) and the diameter of the cell there (the mesh size
     * at that point).
     */
    std::vector<double> von_mises_position;
    double              von_mises_cell_diameter = 0;
  };

  /**
   * The last box of the data path: rotates the solution back to Cartesian
   * coordinates, converts it to the scene's units (PhysicalMapping: the
   * mesh times L, displacements times L, stresses times S) and computes
   * what users look at (contact force, error norms, field maxima), then
   * writes every output file into the staging directory of an
   * OutputDirectory and publishes them there, all at once.
   *
   * Distributed: every process integrates over its own cells and writes
   * one VTU piece of them (VtuOutput); the numbers are summed over the
   * processes, the contact table gathered (ContactTable), and the first
   * process writes the other files.
   */
  template <int dim>
  class Postprocessor
  {
  public:
    /**
     * With @p friction (the problem's friction terms), contact.csv and
     * the contact surface have the friction columns (ContactRow).
     */
    Postprocessor(const Discretization<dim> &      discretization,
                  const Parameters::AllParameters &parameters,
                  const FrictionTerms *            friction = nullptr);

    /**
     * Solution (finest level, rotated basis, dimensionless) -> Cartesian
     * active vector in the scene's units (for get_mapping()), with its
     * ghost values.
     */
    LevelVector solution_in_scene_units(const LevelVector &x_rotated) const;

    /** The mapping of the mesh onto the scene's coordinates. */
    const Mapping<dim> &get_mapping() const { return mapping; }

    /**
     * The resultant of the traction on each boundary id of the scene
     * (Dirichlet, Neumann and contact ids): the integral of sigma n over
     * the id's faces, with sigma the computed stress and n the body's
     * outward normal, of the solution_in_scene_units(). It is the force
     * that the body's surroundings (the obstacle, the support, the load)
     * exert on the body there; in 2D per unit length out of plane. By the
     * divergence theorem their sum is the integral of div sigma over the
     * body, the equilibrium residual's resultant (0 in equilibrium without
     * body force). Collective.
     */
    std::map<types::boundary_id, Tensor<1, dim>>
    boundary_forces(const LevelVector &solution) const;

    /** Total contact force: the @p forces (boundary_forces()) of the contact ids, added. */
    Tensor<1, dim>
    contact_force(const std::map<types::boundary_id, Tensor<1, dim>> &forces) const;

    /**
     * Error norms of the solution_in_scene_units() against Data/Exact
     * displacement and Exact stress.
     */
    ErrorNorms errors(const LevelVector &solution) const;

    /**
     * The same norms of the difference of two functions on this mesh,
     * @p a - @p b (solution_in_scene_units() of two solutions, or one
     * carried over from a coarser mesh): the error against a reference
     * solution (Adaptivity/Reference refinements).
     */
    ErrorNorms difference(const LevelVector &a, const LevelVector &b) const;

    /**
     * The largest |u| and von Mises stress of the solution_in_scene_units()
     * at the corners of the cells (where the Q1 and RT0 fields take their
     * extremes in a cell); collective.
     */
    FieldMaxima field_maxima(const LevelVector &solution) const;

    /**
     * Write the VTU pieces (+pvtu) of step @p step of the run and the pvd
     * series of its steps so far into @p output, unless Output/Write vtu
     * is false, and for an adaptive run with contact the step's contact
     * table, contact_<step>.csv (collective). A failure to write stops the run on every
     * process, with nothing published. Returns the step's contact table
     * (as contact.csv has it) in an adaptive run, on the first process
     * ("" elsewhere and in a run without adaptivity).
     */
    std::string write_step(const LevelVector &         x_rotated,
                           const ErrorIndicators<dim> &indicators,
                           const unsigned int          step,
                           OutputDirectory &           output) const;

    /**
     * Write contact.csv, convergence.csv, summary.json,
     * used_parameters.prm and the @p extra_files (name -> contents) into
     * @p output and publish them with the VTU files of write_step()
     * (collective). @p summary holds the JSON fields (already formatted
     * values).
     */
    void write(const LevelVector &                        x_rotated,
               const Monitor &                            monitor,
               const std::map<std::string, std::string> &summary,
               const std::string &                        used_parameters,
               const std::map<std::string, std::string> &extra_files,
               OutputDirectory &                          output) const;
    /**
     * The same with the texts of contact.csv and convergence.csv given:
     * those of a step finished before (an interrupted adaptive run
     * publishes its last finished step, FoslsProblem::run()).
     */
    void write(const std::string &                        contact_table,
               const std::string &                        convergence,
               const std::map<std::string, std::string> &summary,
               const std::string &                        used_parameters,
               const std::map<std::string, std::string> &extra_files,
               OutputDirectory &                          output) const;

  private:
    const Discretization<dim> &     discretization;
    const Parameters::AllParameters parameters;
    const ReferenceScales           scaling;
    const PhysicalMapping<dim>      mapping;
    const FrictionTerms *           friction;
  };
} // namespace FoslsContact

#endif
