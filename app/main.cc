/**
 * fosls-contact: frictionless linear elastic contact (Signorini's problem)
 * in first-order system least-squares form, solved by a monotone multilevel
 * method.
 *
 *   fosls-contact SCENE.prm [--set "Section/Name=value" ...]
 *
 *   mpirun -np N fosls-contact SCENE.prm [...]
 *
 * main() only reads the parameters and hands them to FoslsProblem; every
 * error ends in one line on stderr and exit code 1, before any output file
 * is written. (On several processes, an error that not all of them meet,
 * which bad input never is, ends in MPI_Abort: mpirun then adds its own
 * report, unless started with --quiet, and sets the exit code.)
 *
 * The program runs on every process of MPI_COMM_WORLD (one, or those
 * mpirun starts), each using its share of the machine's cores with
 * threads (Solver/Threads).
 */
#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <fosls_contact/fosls_problem.h>
#include <fosls_contact/parameters.h>

#include <chrono>
#include <filesystem>
#include <thread>
#include <iostream>
#include <sstream>

namespace
{
  /** The one-line text of an exception, without deal.II's stack trace. */
  std::string
  one_line(const std::exception &exc)
  {
    std::string text;
    if (const auto *e = dynamic_cast<const dealii::ExceptionBase *>(&exc))
      {
        std::ostringstream info;
        e->print_info(info);
        text = info.str();
        if (text.find("Additional information:") != std::string::npos)
          text = text.substr(text.find("Additional information:") + 23);
      }
    else
      text = exc.what();
    std::string out;
    bool        space = false;
    for (const char c : text)
      if (std::isspace(static_cast<unsigned char>(c)))
        space = !out.empty();
      else
        {
          if (space)
            out += ' ';
          out += c;
          space = false;
        }
    return out;
  }

  /**
   * End the program after an error with @p line: with one process, print
   * it and return 1. With several, the processes that fail agree on a
   * separate communicator: if all of them failed (an error every process
   * meets: bad input, a bad scene), the first prints the line and all
   * return 1; if some did not come within 10 s (they wait in a collective
   * operation: an error of one process), this one prints its line and
   * aborts the run.
   */
  int
  stop_with_error(const std::string &line, const MPI_Comm error_comm)
  {
    int n_processes = 1, rank = 0;
    MPI_Comm_size(error_comm, &n_processes);
    MPI_Comm_rank(error_comm, &rank);
    if (n_processes == 1)
      {
        std::cerr << line << std::endl;
        return 1;
      }
    MPI_Request request;
    MPI_Ibarrier(error_comm, &request);
    int        done = 0;
    const auto start = std::chrono::steady_clock::now();
    while (!done && std::chrono::steady_clock::now() - start < std::chrono::seconds(10))
      {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (!done)
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    if (done)
      {
        if (rank == 0)
          std::cerr << line << std::endl;
        return 1;
      }
    std::cerr << line << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }

  /** Apply one --set "Section/Subsection/Name=value". */
  void
  apply_override(dealii::ParameterHandler &prm, const std::string &assignment)
  {
    const auto eq = assignment.find('=');
    AssertThrow(eq != std::string::npos,
                dealii::ExcMessage("--set '" + assignment +
                                   "' is not of the form Section/Name=value"));
    const auto path =
      dealii::Utilities::split_string_list(assignment.substr(0, eq), '/');
    const std::string value = dealii::Utilities::trim(assignment.substr(eq + 1));
    AssertThrow(path.size() >= 2,
                dealii::ExcMessage("--set '" + assignment +
                                   "' needs a section: Section/Name=value"));
    for (unsigned int i = 0; i + 1 < path.size(); ++i)
      prm.enter_subsection(path[i]);
    try
      {
        prm.set(path.back(), value);
      }
    catch (const dealii::ParameterHandler::ExcEntryUndeclared &)
      {
        AssertThrow(false,
                    dealii::ExcMessage("--set: unknown parameter '" +
                                       assignment.substr(0, eq) + "'"));
      }
    catch (const dealii::ParameterHandler::ExcValueDoesNotMatchPattern &)
      {
        AssertThrow(false,
                    dealii::ExcMessage("--set: invalid value '" + value +
                                       "' for parameter '" +
                                       assignment.substr(0, eq) + "'"));
      }
    for (unsigned int i = 0; i + 1 < path.size(); ++i)
      prm.leave_subsection();
  }
} // namespace


int
main(int argc, char *argv[])
{
  using namespace FoslsContact;
  // threads: as many as cores (or DEAL_II_NUM_THREADS) until the scene's
  // Solver/Threads says otherwise
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv,
                                               dealii::numbers::invalid_unsigned_int);
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();

  MPI_Comm error_comm;
  MPI_Comm_dup(MPI_COMM_WORLD, &error_comm);
  const bool  first_rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::string where      = "command line";
  try
    {
      std::string              file;
      std::vector<std::string> overrides;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--set")
            {
              AssertThrow(i + 1 < argc,
                          dealii::ExcMessage("--set needs an argument"));
              overrides.push_back(argv[++i]);
            }
          else if (arg.rfind("--set=", 0) == 0)
            overrides.push_back(arg.substr(6));
          else if (arg == "--print-parameters")
            {
              // every parameter with its default, pattern and documentation,
              // as JSON: scripts/make_parameter_doc.py turns it into
              // doc/parameters.md
              dealii::ParameterHandler prm;
              Parameters::AllParameters::declare_parameters(prm);
              if (first_rank)
                prm.print_parameters(std::cout, dealii::ParameterHandler::JSON);
              MPI_Comm_free(&error_comm);
              return 0;
            }
          else if (arg == "--help" || arg == "-h")
            {
              if (first_rank)
                std::cout << "usage: fosls-contact SCENE.prm [--set "
                             "\"Section/Name=value\" ...]\n"
                             "       mpirun -np N fosls-contact SCENE.prm [...]\n"
                             "       fosls-contact --print-parameters\n";
              MPI_Comm_free(&error_comm);
              return 0;
            }
          else
            {
              AssertThrow(arg.empty() || arg[0] != '-',
                          dealii::ExcMessage("unknown option '" + arg +
                                             "' (options: --set, --print-parameters, --help)"));
              AssertThrow(file.empty(),
                          dealii::ExcMessage("more than one parameter file "
                                             "given ('" + file + "', '" + arg +
                                             "')"));
              file = arg;
            }
        }
      AssertThrow(!file.empty(),
                  dealii::ExcMessage("no parameter file given; usage: "
                                     "fosls-contact SCENE.prm [--set "
                                     "\"Section/Name=value\" ...]"));
      AssertThrow(!std::filesystem::is_directory(file),
                  dealii::ExcMessage("parameter file '" + file + "' is a directory"));
      AssertThrow(std::filesystem::is_regular_file(file),
                  dealii::ExcMessage("parameter file '" + file +
                                     "' does not exist"));

      dealii::ParameterHandler prm;
      Parameters::AllParameters::declare_parameters(prm);
      where = file;
      prm.parse_input(file);
      where = file + " (--set)";
      for (const auto &o : overrides)
        apply_override(prm, o);
      where = file;
      Parameters::AllParameters parameters;
      parameters.parse_parameters(prm);

      if (parameters.solver.threads > 0)
        dealii::MultithreadInfo::set_thread_limit(parameters.solver.threads);

      std::ostringstream used;
      prm.print_parameters(used, dealii::ParameterHandler::PRM);

      if (parameters.geometry.dimension == 2)
        FoslsProblem<2>(parameters, used.str()).run();
      else
        FoslsProblem<3>(parameters, used.str()).run();
    }
  catch (const std::exception &exc)
    {
      return stop_with_error("fosls-contact: error in " + where + ": " + one_line(exc),
                             error_comm);
    }
  catch (...)
    {
      return stop_with_error("fosls-contact: unknown error in " + where, error_comm);
    }
  MPI_Comm_free(&error_comm);
  return 0;
}
