#ifndef fosls_contact_output_vtu_output_h
#define fosls_contact_output_vtu_output_h

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/output/output_directory.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/qp/constrained_qp.h>
#include <fosls_contact/scene/physical_mapping.h>

#include <string>

namespace FoslsContact
{
  /**
   * The pictures of a run: the solution's VTU pieces (one per process),
   * their pvtu records and the pvd series that ParaView opens, for the body
   * and its contact surface. Drawing has concerns of its own (a curved
   * boundary drawn with a quadratic mapping, VTK's active fields, the
   * compression level) that the numbers of the Postprocessor do not share.
   */
  template <int dim>
  class VtuOutput
  {
  public:
    /** With @p friction, the contact surface shows the friction fields. */
    VtuOutput(const Discretization<dim> &   discretization,
              const Parameters::Material &  material,
              const PhysicalMapping<dim> &  mapping,
              const FrictionTerms *         friction = nullptr);

    /**
     * The solution's VTU piece of this process (the fields of
     * StressFields, the error indicators, the contact status), and on the
     * first process the pvtu record and the pvd series; with contact, the
     * same for the ContactSurface. @p solution is @p x_rotated in the
     * scene's units (Postprocessor::solution_in_scene_units()). The files
     * are those of step @p step of an adaptive run (solution_0000 ... );
     * the pvd series lists the steps 0 to @p step as its time steps.
     */
    void write(const LevelVector &         x_rotated,
               const LevelVector &         solution,
               const ErrorIndicators<dim> &indicators,
               OutputDirectory &           output,
               const unsigned int          step) const;

  private:
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

    const Discretization<dim> & discretization;
    const Parameters::Material &material;
    const ReferenceScales &     scaling;
    const PhysicalMapping<dim> &mapping;
    const FrictionTerms *       friction;
  };
} // namespace FoslsContact

#endif
