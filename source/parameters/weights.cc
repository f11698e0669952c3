#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/weights.h>
#include <fosls_contact/parameters/value_parsing.h>

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
                        "0.1",
                        Patterns::Double(0),
                        "Weight of the complementarity term <u.n - g, (sigma n).n> "
                        "(paper eq. 2). Too large a value makes the problem "
                        "indefinite; the program checks and refuses. The "
                        "paper's 1e1 is indefinite with C_const = 1 (see "
                        "doc/method.md, section 5), hence the default 0.1. The "
                        "three weights apply to the dimensionless terms "
                        "(Scaling), so they mean the same in every unit system.");
      prm.leave_subsection();
    }

    void
    Weights::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Functional weights");
      c_eq    = prm.get_double("C_eq");
      c_const = prm.get_double("C_const");
      c_compl = prm.get_double("C_compl");
      const std::string eq_text = prm.get("C_eq"), const_text = prm.get("C_const");
      prm.leave_subsection();
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
