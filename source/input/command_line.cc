#include <fosls_contact/base/build_info.h>
#include <fosls_contact/base/error_line.h>
#include <fosls_contact/input/command_line.h>

namespace FoslsContact
{
  CommandLine::CommandLine(const int argc, const char *const *argv)
  {
    const std::string where = "command line";
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--set")
          {
            if (i + 1 >= argc)
              throw InputError(where, "--set needs an argument \"Section/Name=value\"");
            overrides.push_back(argv[++i]);
          }
        else if (arg.rfind("--set=", 0) == 0)
          overrides.push_back(arg.substr(6));
        else if (arg == "--print-parameters")
          print_parameters = true;
        else if (arg == "--help" || arg == "-h")
          help = true;
        else if (arg == "--version")
          version = true;
        else if (!arg.empty() && arg[0] == '-')
          throw InputError(where,
                           "unknown option '" + ErrorLine::quote(arg) +
                             "' (options: --set, --print-parameters, --help, --version)");
        else if (!scene.empty())
          throw InputError(where,
                           "more than one parameter file given ('" + ErrorLine::quote(scene) +
                             "', '" + ErrorLine::quote(arg) + "')");
        else if (arg.empty())
          throw InputError(where, "the parameter file name is empty");
        else
          scene = arg;
      }
    if (help || version)
      return;
    if (scene.empty() && !print_parameters)
      throw InputError(where,
                       "no parameter file given; usage: fosls-contact SCENE.prm "
                       "[--set \"Section/Name=value\" ...] (--help for more)");
    if (scene.empty() && !overrides.empty())
      throw InputError(where,
                       "--set with --print-parameters needs a parameter file: "
                       "fosls-contact --print-parameters SCENE.prm --set ...");
  }


  std::string
  CommandLine::help_text()
  {
    return "usage: fosls-contact SCENE [--set \"Section/Name=value\" ...]\n"
           "       mpirun -np N fosls-contact SCENE [--set ...]\n"
           "       fosls-contact --print-parameters [SCENE [--set ...]]\n"
           "       fosls-contact --help | --version\n"
           "\n"
           "Computes the contact of a linear elastic body with a rigid obstacle\n"
           "(Signorini's problem; frictionless, or with Tresca or Coulomb friction\n"
           "over load steps) in FOSLS form with a monotone multilevel solver, for\n"
           "the scene described in SCENE.\n"
           "\n"
           "  SCENE                 the parameter file: .prm (may 'include' other\n"
           "                        files, relative to the including file), .json (as\n"
           "                        --print-parameters writes it) or .xml\n"
           "  --set \"S/Name=value\"  override the parameter Name of section S (nested\n"
           "                        sections: S/T/Name); repeatable, the last one\n"
           "                        wins; also --set=S/Name=value\n"
           "  --print-parameters    print every parameter as JSON (value, default,\n"
           "                        pattern, documentation) and exit; with SCENE and\n"
           "                        --set, the values are the scene's\n"
           "  --help, -h            print this help and exit\n"
           "  --version             print the program version, the git revision it was\n"
           "                        built from and the deal.II version, and exit\n"
           "\n"
           "The results go to the scene's Output/Directory: they appear there all at\n"
           "once when the run ends (or not at all); two runs cannot use one directory\n"
           "at the same time. Threads per process: --set \"Solver/Threads=N\".\n"
           "\n"
           "Exit codes:\n"
           "  0  the solver converged; the output files are written\n"
           "  1  error (bad input, unusable Output/Directory, ...): one line on stderr,\n"
           "     'fosls-contact: error in <where>: <what>', and no output files\n"
           "  2  the solver did not converge within Solver/Max iterations: the output\n"
           "     files are written, summary.json has \"converged\": false, and one line\n"
           "     on stderr says so\n"
           "  3  an error that only some MPI processes met, the others stopped by\n"
           "     MPI_Abort: memory that ran out on one process, or a defect of the\n"
           "     program (worth a report)\n"
           "  4  stopped by SIGTERM or SIGINT: an adaptive run publishes the steps it\n"
           "     finished (summary.json has \"interrupted\"), a run without a finished\n"
           "     step writes nothing; one line on stderr says which\n";
  }


  std::string
  CommandLine::version_text()
  {
    return "fosls-contact " + BuildInfo::version() + "\ngit revision " +
           BuildInfo::git_revision() + "\ndeal.II " + BuildInfo::deal_ii_version() + "\n";
  }
} // namespace FoslsContact
