#ifndef fosls_contact_parameters_data_h
#define fosls_contact_parameters_data_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Data: the functions of a scene, as FunctionParser
     * expressions in x, y (, z). Components are separated by `;`. An empty
     * body force means the scene has none: no term is assembled for it.
     */
    struct Data
    {
      std::string body_force;
      std::string dirichlet_values;
      std::string traction;
      std::string gap;
      std::string obstacle_normal;
      std::string exact_displacement;
      std::string exact_stress;
      std::string initial_displacement;
      std::string constants;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
