#ifndef fosls_contact_parameters_output_h
#define fosls_contact_parameters_output_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Output: where the run writes its files and how much it
     * prints; what is written is described in README.md.
     */
    struct Output
    {
      std::string directory = "output";
      bool        write_vtu = true;
      bool        verbose   = true;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
