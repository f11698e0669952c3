#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/weights.h>
#include <fosls_contact/parameters/value_parsing.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    Weights::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Functional weights");
      prm.declare_entry("C_eq",
                        "1e2",
                        Patterns::Double(0),
                        "Weight of ||div sigma + f||^2 (paper eq. 1).");
      prm.declare_entry("C_const",
                        "1",
                        Patterns::Double(0),
                        "Weight of ||A sigma - eps(u)||^2 (paper eq. 1). C_eq and "
                        "C_const may be at most 1e12 apart.");
      prm.declare_entry("C_compl",
                        "auto",
                        Patterns::Anything(),
                        "Weight of the complementarity term <u.n - g, (sigma n).n> "
                        "(paper eq. 2), and with friction of the friction term "
                        "(doc/method.md section 7.7): a number >= 0, or auto. Too large a value "
                        "makes the problem indefinite, and where that limit lies "
                        "depends on the mesh; the program computes it on the "
                        "level of its definiteness check and refuses a number "
                        "beyond it, naming the largest accepted value. auto takes "
                        "0.1, or half the limit where that is less (doc/method.md, "
                        "section 6); the screen, summary.json and "
                        "used_parameters.prm give the value taken. The paper's "
                        "1e1 is indefinite with C_const = 1. The three weights "
                        "apply to the dimensionless terms (Scaling), so they mean "
                        "the same in every unit system.");
      prm.leave_subsection();
    }

    void
    Weights::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Functional weights");
      c_eq    = prm.get_double("C_eq");
      c_const = prm.get_double("C_const");
      const std::string compl_text = Utilities::trim(prm.get("C_compl"));
      const std::string eq_text = prm.get("C_eq"), const_text = prm.get("C_const");
      prm.leave_subsection();
      c_compl_auto = compl_text == "auto";
      c_compl      = auto_compl_cap;
      if (!c_compl_auto)
        {
          c_compl = std::numeric_limits<double>::quiet_NaN();
          try
            {
              std::size_t end = 0;
              const double value = std::stod(compl_text, &end);
              if (end == compl_text.size())
                c_compl = value;
            }
          catch (...)
            {}
          AssertThrow(std::isfinite(c_compl) && c_compl >= 0,
                      ExcMessage("parameter 'Functional weights/C_compl' = " + compl_text +
                                 " must be 'auto' or a number >= 0"));
        }
      AssertThrow(c_eq > 0 && c_const > 0,
                  ExcMessage("parameters 'Functional weights/C_eq' and "
                             "'C_const' must be > 0"));
      // The equilibrium entries of an RT flux are C_eq h^-2 against the
      // constitutive ones' C_const: 12 orders between the weights leave the
      // smaller part a few digits above the round-off of the larger on a
      // coarse mesh, and none on a fine one (bad_input/nan_iterate: 1e12
      // apart on 6 levels gives a NaN iterate).
      constexpr double max_ratio = 1e12;
      AssertThrow(c_eq <= max_ratio * c_const && c_const <= max_ratio * c_eq,
                  ExcMessage("parameters 'Functional weights/C_eq' = " + eq_text +
                             " and 'C_const' = " + const_text +
                             " are more than 1e12 apart: the smaller part of J would "
                             "be lost to the round-off of the larger in double "
                             "precision"));
    }
  } // namespace Parameters
} // namespace FoslsContact
