#ifndef fosls_contact_input_command_line_h
#define fosls_contact_input_command_line_h

#include <fosls_contact/base/exit_code.h>
#include <fosls_contact/base/input_error.h>

#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * The command line of fosls-contact:
   *
   *   fosls-contact SCENE [--set "Section/Name=value" ...]
   *   fosls-contact --print-parameters [SCENE [--set ...]]
   *   fosls-contact --help | --version
   *
   * with the exit codes (ExitCode) in its help text.
   */
  class CommandLine
  {
  public:
    /** Parse @p argv; throws InputError (where: "command line"). */
    CommandLine(const int argc, const char *const *argv);

    /** The scene file ("" if none was given). */
    std::string scene;
    /** The --set arguments, in order. */
    std::vector<std::string> overrides;
    bool                     print_parameters = false;
    bool                     help             = false;
    bool                     version          = false;

    /** The --help text: every option and the exit codes. */
    static std::string help_text();
    /** The --version text: program version, git revision, deal.II version. */
    static std::string version_text();
  };
} // namespace FoslsContact

#endif
