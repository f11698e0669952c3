#ifndef fosls_contact_output_stress_fields_h
#define fosls_contact_output_stress_fields_h

#include <deal.II/numerics/data_postprocessor.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/scene/scene.h>

namespace FoslsContact
{
  /**
   * The fields engineers read, derived point by point from the solution in
   * the scene's units (Postprocessor::solution_in_scene_units(), with the
   * PhysicalMapping): the stress as a symmetric tensor (the symmetric part
   * of the FOSLS stress), the von Mises stress, the hydrostatic pressure,
   * in 2D the plane-strain out-of-plane stress sigma_zz
   * (StressMeasures), and the equilibrium residual div sigma + f.
   */
  template <int dim>
  class StressFields : public DataPostprocessor<dim>
  {
  public:
    StressFields(const Scene<dim> &scene, const Parameters::Material &material);

    void evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                               std::vector<Vector<double>> &computed) const override;
    std::vector<std::string> get_names() const override;
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
               get_data_component_interpretation() const override;
    UpdateFlags get_needed_update_flags() const override;

  private:
    const Scene<dim> &scene;
    const double      poisson_ratio;
  };
} // namespace FoslsContact

#endif
