#ifndef fosls_contact_output_postprocessor_h
#define fosls_contact_output_postprocessor_h

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/output/monitor.h>
#include <fosls_contact/output/output_directory.h>
#include <fosls_contact/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/physical_mapping.h>

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
   * A row of the contact table (Postprocessor::contact_rows(), contact.csv):
   * the positions of its entries.
   */
  template <int dim>
  struct ContactRow
  {
    static constexpr unsigned int x        = 0;       ///< position (dim)
    static constexpr unsigned int u        = dim;     ///< displacement (dim)
    static constexpr unsigned int u_n      = 2 * dim; ///< normal displacement
    static constexpr unsigned int gap      = 2 * dim + 1;
    static constexpr unsigned int sigma_nn = 2 * dim + 2; ///< mean normal traction
    static constexpr unsigned int active   = 2 * dim + 3; ///< 1 in contact, else 0
    static constexpr unsigned int size     = 2 * dim + 4;
    using Values                           = std::array<double, size>;
  };

  /** Extremes of the fields, in the scene's units. */
  struct FieldMaxima
  {
    double displacement = 0; ///< max |u|
    double von_mises    = 0; ///< max of the von Mises stress (StressMeasures)
  };

  /**
   * The last box of the data path: rotates the solution back to Cartesian
   * coordinates, converts it to the scene's units (PhysicalMapping: the
   * mesh times L, displacements times L, stresses times S) and computes
   * what users look at (contact force, contact table, error norms), then
   * writes every output file into the staging directory of an
   * OutputDirectory and publishes them there, all at once.
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
     * Solution (finest level, rotated basis, dimensionless) -> Cartesian
     * active vector in the scene's units (for get_mapping()), with its
     * ghost values.
     */
    LevelVector solution_in_scene_units(const LevelVector &x_rotated) const;

    /** The mapping of the mesh onto the scene's coordinates. */
    const Mapping<dim> &get_mapping() const { return mapping; }

    /**
     * Total contact force: the integral of sigma n over Gamma_C, of the
     * solution_in_scene_units().
     */
    Tensor<1, dim> contact_force(const LevelVector &solution) const;

    /**
     * Error norms of the solution_in_scene_units() against Data/Exact
     * displacement and Exact stress.
     */
    ErrorNorms errors(const LevelVector &solution) const;

    /**
     * The largest |u| and von Mises stress of the solution_in_scene_units()
     * at the corners of the cells (where the Q1 and RT0 fields take their
     * extremes in a cell); collective.
     */
    FieldMaxima field_maxima(const LevelVector &solution) const;

    /**
     * One row per contact vertex of the finest level, sorted by position,
     * in the scene's units (ContactRow): the position, the displacement,
     * u_n, the gap, sigma_nn (the mean over the contact faces at the
     * vertex) and 1 if the vertex is in contact (u_n = g), else 0. On the
     * first process; collective.
     */
    std::vector<typename ContactRow<dim>::Values>
    contact_rows(const LevelVector &x_rotated) const;

    /** contact_rows() as CSV text (on the first process; collective). */
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
               const ErrorIndicators<dim> &               indicators,
               OutputDirectory &                          output) const;

  private:
    /**
     * The solution's VTU piece of this process (the fields of
     * StressFields, the error indicators, the contact status), and on the
     * first process the pvtu record and the pvd series; with contact, the
     * same for the ContactSurface.
     */
    void write_vtu(const LevelVector &         x_rotated,
                   const ErrorIndicators<dim> &indicators,
                   OutputDirectory &           output) const;
    /**
     * Write the piece @p name.<process>.vtu of @p writer (a DataOut or
     * DataOutFaces after build_patches) and, on the first process, the
     * record @p name.pvtu, both naming the @p active fields.
     */
    template <typename Writer>
    void write_pieces(Writer &           writer,
                      const std::string &name,
                      const std::string &active,
                      OutputDirectory &  output) const;

    const Discretization<dim> &     discretization;
    const Parameters::AllParameters parameters;
    const Scaling                   scaling;
    const PhysicalMapping<dim>      mapping;
  };
} // namespace FoslsContact

#endif
