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
                        "Weight of ||A sigma - eps(u)||^2 (paper eq. 1).");
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
      prm.leave_subsection();
      AssertThrow(c_eq > 0 && c_const > 0,
                  ExcMessage("parameters 'Functional weights/C_eq' and "
                             "'C_const' must be > 0"));
    }
  } // namespace Parameters
} // namespace FoslsContact
