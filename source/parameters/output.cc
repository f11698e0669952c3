#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/output.h>
#include <fosls_contact/parameters/value_parsing.h>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Directory for VTU, CSV and JSON output (created).");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write the solution as pvtu + vtu.");
      prm.declare_entry("Verbose",
                        "true",
                        Patterns::Bool(),
                        "Print one line per iteration and the timer summary.");
      prm.leave_subsection();
    }

    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory = prm.get("Directory");
      write_vtu = prm.get_bool("Write vtu");
      verbose   = prm.get_bool("Verbose");
      prm.leave_subsection();
      AssertThrow(!Utilities::trim(directory).empty(),
                  ExcMessage("parameter 'Output/Directory' is empty"));
    }
  } // namespace Parameters
} // namespace FoslsContact
