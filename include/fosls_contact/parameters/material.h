#ifndef fosls_contact_parameters_material_h
#define fosls_contact_parameters_material_h

#include <deal.II/base/parameter_handler.h>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Material: the elastic constants, given either as the Lame
     * parameters (mu, lambda) or as Young's modulus and Poisson's ratio
     * (E, nu), exactly one of the two pairs, in any consistent units. The
     * other pair is computed; lambda = inf and nu = 0.5 are the
     * incompressible material.
     */
    struct Material
    {
      double mu     = 1.;
      double lambda = 1.; ///< +infinity for incompressible material
      double youngs_modulus = 2.5;  ///< E
      double poisson_ratio  = 0.25; ///< nu
      /** Whether the scene gave E and nu (else mu and lambda). */
      bool given_as_e_nu = false;

      /**
       * The parameter mu comes from, for messages: "parameter
       * 'Material/mu'", or "parameters 'Material/E' and 'nu' (mu = E / (2
       * (1 + nu)))".
       */
      std::string mu_source() const;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
