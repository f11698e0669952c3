#ifndef fosls_contact_parameters_weights_h
#define fosls_contact_parameters_weights_h

#include <deal.II/base/parameter_handler.h>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /** subsection Functional weights: C_eq, C_const, C_compl of eq. (1)-(2). */
    struct Weights
    {
      double c_eq    = 1e2;
      double c_const = 1.;
      double c_compl = 0.1;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
