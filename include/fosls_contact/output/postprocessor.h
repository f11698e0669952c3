#ifndef fosls_contact_output_postprocessor_h
#define fosls_contact_output_postprocessor_h

#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/output/monitor.h>
#include <fosls_contact/output/output_directory.h>
#include <fosls_contact/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>

#include <map>
#include <string>

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
  };

  /**
   * The last box of the data path: rotates the solution back to Cartesian
   * coordinates and computes what users look at (contact force, contact
   * table, error norms), then writes every output file into the staging
   * directory of an OutputDirectory and publishes them there, all at once.
   *
   * Distributed: every process integrates over its own cells and writes
   * one VTU piece of them; the numbers are summed over the processes, the
   * contact table gathered (rows sorted by position), and the first
   * process writes the other files.
   */
  template <int dim>
  class Postprocessor
  {
  public:
    Postprocessor(const Discretization<dim> &   discretization,
                  const Parameters::AllParameters &parameters);

    /**
     * Solution (finest level, rotated basis) -> Cartesian active vector,
     * with its ghost values.
     */
    LevelVector cartesian_active(const LevelVector &x_rotated) const;

    /** Total contact force: the integral of sigma n over Gamma_C. */
    Tensor<1, dim> contact_force(const LevelVector &active_solution) const;

    /** Error norms against Data/Exact displacement and Exact stress. */
    ErrorNorms errors(const LevelVector &active_solution) const;

    /**
     * One row per contact vertex of the finest level, sorted by position
     * (on the first process; collective).
     */
    std::string contact_table(const LevelVector &x_rotated) const;

    /**
     * Write VTU (+pvtu), contact.csv, convergence.csv, summary.json and
     * used_parameters.prm into @p output and publish them (collective).
     * @p summary holds the JSON fields (already formatted values).
     */
    void write(const LevelVector &                        x_rotated,
               const Monitor &                            monitor,
               const std::map<std::string, std::string> &summary,
               const std::string &                        used_parameters,
               OutputDirectory &                          output) const;

  private:
    /** The solution's VTU piece of this process, and on the first the pvtu record. */
    void write_vtu(const LevelVector &x_rotated, OutputDirectory &output) const;

    const Discretization<dim> &     discretization;
    const Parameters::AllParameters parameters;
  };
} // namespace FoslsContact

#endif
