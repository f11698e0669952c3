#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/material.h>
#include <fosls_contact/parameters/value_parsing.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    Material::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("mu",
                        "",
                        Patterns::Anything(),
                        "Shear modulus mu > 0, given with lambda. The material is "
                        "given either by mu and lambda or by E and nu (exactly one "
                        "pair), in any consistent units.");
      prm.declare_entry("lambda",
                        "",
                        Patterns::Anything(),
                        "Lame's first parameter lambda, given with mu: a number "
                        "> -2 mu / dim (a positive bulk modulus), or 'inf' for an "
                        "incompressible material (exact, no penalty).");
      prm.declare_entry("E",
                        "",
                        Patterns::Anything(),
                        "Young's modulus E > 0, given with nu (instead of mu and "
                        "lambda).");
      prm.declare_entry("nu",
                        "",
                        Patterns::Anything(),
                        "Poisson's ratio nu, -1 < nu <= 0.5, given with E; 0.5 is the "
                        "incompressible material (lambda = inf). In 2D the body is "
                        "in plane strain.");
      prm.leave_subsection();
    }

    void
    Material::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      const std::string mu_text     = Utilities::trim(prm.get("mu"));
      const std::string lambda_text = Utilities::trim(prm.get("lambda"));
      const std::string e_text      = Utilities::trim(prm.get("E"));
      const std::string nu_text     = Utilities::trim(prm.get("nu"));
      prm.leave_subsection();

      const bool lame        = !mu_text.empty() || !lambda_text.empty();
      const bool engineering = !e_text.empty() || !nu_text.empty();
      given_as_e_nu          = engineering;
      AssertThrow(lame != engineering,
                  ExcMessage(std::string("subsection 'Material' needs exactly one pair of "
                                         "constants, 'mu' and 'lambda' or 'E' and 'nu'; ") +
                             (lame ? "both pairs are given" : "none is given")));
      if (lame)
        {
          AssertThrow(!mu_text.empty() && !lambda_text.empty(),
                      ExcMessage(std::string("parameter 'Material/") +
                                 (mu_text.empty() ? "lambda' is given without 'Material/mu'" :
                                                    "mu' is given without 'Material/lambda'")));
          mu     = parse_extended_double(mu_text, "Material/mu");
          lambda = parse_extended_double(lambda_text, "Material/lambda");
          AssertThrow(std::isfinite(mu) && mu > 0,
                      ExcMessage("parameter 'Material/mu' = " + mu_text +
                                 " must be a number > 0"));
          // (the bound on lambda, which depends on the dimension, is
          // checked by AllParameters::parse_parameters)
          youngs_modulus = std::isinf(lambda) ? 3. * mu :
                                                mu * (3. * lambda + 2. * mu) / (lambda + mu);
          poisson_ratio  = std::isinf(lambda) ? 0.5 : lambda / (2. * (lambda + mu));
        }
      else
        {
          AssertThrow(!e_text.empty() && !nu_text.empty(),
                      ExcMessage(std::string("parameter 'Material/") +
                                 (e_text.empty() ? "nu' is given without 'Material/E'" :
                                                   "E' is given without 'Material/nu'")));
          youngs_modulus = parse_extended_double(e_text, "Material/E");
          poisson_ratio  = parse_extended_double(nu_text, "Material/nu");
          AssertThrow(std::isfinite(youngs_modulus) && youngs_modulus > 0,
                      ExcMessage("parameter 'Material/E' = " + e_text +
                                 " must be a number > 0"));
          AssertThrow(poisson_ratio > -1 && poisson_ratio <= 0.5,
                      ExcMessage("parameter 'Material/nu' = " + nu_text +
                                 " must lie in (-1, 0.5]"));
          const double nu = poisson_ratio;
          mu              = youngs_modulus / (2. * (1. + nu));
          lambda          = nu == 0.5 ? std::numeric_limits<double>::infinity() :
                                        youngs_modulus * nu / ((1. + nu) * (1. - 2. * nu));
        }
    }

    std::string
    Material::mu_source() const
    {
      if (!given_as_e_nu)
        return "parameter 'Material/mu'";
      // (the values as the scene gives them: mu is the program's)
      std::ostringstream text;
      text << "parameters 'Material/E' = " << youngs_modulus << " and 'nu' = " << poisson_ratio
           << " (mu = E / (2 (1 + nu)))";
      return text.str();
    }
  } // namespace Parameters
} // namespace FoslsContact
