#ifndef fosls_contact_parameters_scaling_h
#define fosls_contact_parameters_scaling_h

#include <deal.II/base/parameter_handler.h>

#include <fosls_contact/parameters/unit_names.h>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Scaling: the reference length L and stress S that make the
     * problem dimensionless (doc/method.md, section 1). A value of 0 means
     * "derive it": L from the coarse mesh (the largest side of its bounding
     * box), S = mu. The names of the units label the answers (UnitNames).
     */
    struct Scaling
    {
      double reference_length = 0.;
      double reference_stress = 0.;
      UnitNames unit_names;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
