#ifndef fosls_contact_input_command_line_h
#define fosls_contact_input_command_line_h

#include <fosls_contact/input/input_error.h>

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
   * and the exit codes the program ends with.
   */
  class CommandLine
  {
  public:
    /** The exit codes (documented in help() and the README). */
    enum ExitCode : int
    {
      /** The run converged and its output files are written. */
      success = 0,
      /** An error (bad input, ...): one line on stderr, no output files. */
      error = 1,
      /**
       * The solver did not converge (iteration limit): the output files
       * are written, summary.json says "converged": false, and one line
       * on stderr says so.
       */
      not_converged = 2,
      /**
       * An error that some MPI processes met and the others did not learn
       * of (they waited in a collective call): the line of a process that
       * met it, the run stopped by MPI_Abort. The errors the program
       * expects (bad data, unreadable files, the gathering process's
       * memory) are decided by all processes (exit code 1), so this one is
       * memory that ran out on one process, or a defect of the program.
       */
      error_on_some_processes = 3,
      /**
       * Stopped by SIGTERM or SIGINT (Interruption): an adaptive run has
       * published the steps it finished, summary.json says "interrupted";
       * a run without a finished step has written nothing. One line on
       * stderr says which.
       */
      interrupted = 4,
    };

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
