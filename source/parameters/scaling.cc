#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/scaling.h>
#include <fosls_contact/parameters/value_parsing.h>

#include <cmath>
#include <string>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    Scaling::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scaling");
      prm.declare_entry("Reference length",
                        "auto",
                        Patterns::Anything(),
                        "The length L the program divides all lengths by, in the "
                        "scene's units: a number > 0, or auto: the largest side of "
                        "the bounding box of the coarse mesh. The problem is solved "
                        "in dimensionless form and every output is in the scene's "
                        "units; the functional weights mean the same functional in "
                        "every unit system for the same L (doc/method.md, section 1). "
                        "Models that are parts of one another (a symmetric half) "
                        "need the same L to have the same functional.");
      prm.declare_entry("Reference stress",
                        "auto",
                        Patterns::Anything(),
                        "The stress S the program divides all stresses by, in the "
                        "scene's units: a number > 0, or auto: the shear modulus mu.");
      prm.declare_entry("Unit names",
                        "",
                        Patterns::Anything(),
                        "The names of the scene's units, e.g. 'length=mm, force=N, "
                        "stress=MPa' (each of length, force and stress once), or empty: "
                        "the scene's units, unnamed. They label the answers on the "
                        "screen, in summary.json (units) and on the axes of "
                        "scripts/plot.py; in 2D a force is per unit length out of plane "
                        "(N/mm). Labels only: the scene's numbers must be in these units, "
                        "and consistent (stress = force / length^2), which the program "
                        "does not check.");
      prm.leave_subsection();
    }

    void
    Scaling::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scaling");
      const std::string length_text = Utilities::trim(prm.get("Reference length"));
      const std::string stress_text = Utilities::trim(prm.get("Reference stress"));
      const std::string unit_text   = prm.get("Unit names");
      prm.leave_subsection();
      auto parse = [](const std::string &text, const std::string &name) {
        if (text == "auto")
          return 0.;
        const double value = parse_extended_double(text, name);
        AssertThrow(std::isfinite(value) && value > 0,
                    ExcMessage("parameter '" + name + "' = " + text +
                               " must be 'auto' or a number > 0"));
        return value;
      };
      reference_length = parse(length_text, "Scaling/Reference length");
      reference_stress = parse(stress_text, "Scaling/Reference stress");
      unit_names.parse(unit_text, "Scaling/Unit names");
    }
  } // namespace Parameters
} // namespace FoslsContact
