#include <fosls_contact/output/stress_fields.h>
#include <fosls_contact/output/stress_measures.h>

namespace FoslsContact
{
  template <int dim>
  StressFields<dim>::StressFields(const Scene<dim> &scene, const Parameters::Material &material)
    : scene(scene)
    , poisson_ratio(material.poisson_ratio)
  {}


  template <int dim>
  std::vector<std::string>
  StressFields<dim>::get_names() const
  {
    std::vector<std::string> names(dim * dim, "stress");
    names.emplace_back("von_mises");
    names.emplace_back("pressure");
    if (dim == 2)
      names.emplace_back("stress_zz");
    for (unsigned int d = 0; d < dim; ++d)
      names.emplace_back("div_sigma_plus_f");
    return names;
  }


  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressFields<dim>::get_data_component_interpretation() const
  {
    using namespace DataComponentInterpretation;
    std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds(
      dim * dim, component_is_part_of_tensor);
    kinds.push_back(component_is_scalar);
    kinds.push_back(component_is_scalar);
    if (dim == 2)
      kinds.push_back(component_is_scalar);
    for (unsigned int d = 0; d < dim; ++d)
      kinds.push_back(component_is_part_of_vector);
    return kinds;
  }


  template <int dim>
  UpdateFlags
  StressFields<dim>::get_needed_update_flags() const
  {
    return update_values | update_gradients | update_quadrature_points;
  }


  template <int dim>
  void
  StressFields<dim>::evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                                           std::vector<Vector<double>> &computed) const
  {
    Vector<double> f(dim);
    for (unsigned int q = 0; q < computed.size(); ++q)
      {
        // row m of sigma is the FE field dim + m dim .. dim + m dim + dim - 1
        Tensor<2, dim> sigma;
        for (unsigned int m = 0; m < dim; ++m)
          for (unsigned int k = 0; k < dim; ++k)
            sigma[m][k] = inputs.solution_values[q][dim + m * dim + k];
        const SymmetricTensor<2, 3> s = StressMeasures::full_stress(sigma, poisson_ratio);
        unsigned int            c = 0;
        for (unsigned int m = 0; m < dim; ++m)
          for (unsigned int k = 0; k < dim; ++k)
            computed[q][c++] = s[m][k];
        computed[q][c++] = StressMeasures::von_mises(sigma, poisson_ratio);
        computed[q][c++] = StressMeasures::pressure(sigma, poisson_ratio);
        if (dim == 2)
          computed[q][c++] = s[2][2];
        if (scene.has_body_force())
          scene.body_force_in_scene_units().vector_value(inputs.evaluation_points[q], f);
        for (unsigned int m = 0; m < dim; ++m)
          {
            double div = 0;
            for (unsigned int k = 0; k < dim; ++k)
              div += inputs.solution_gradients[q][dim + m * dim + k][k];
            computed[q][c++] = div + f[m];
          }
      }
  }

  template class StressFields<2>;
  template class StressFields<3>;
} // namespace FoslsContact
