/**
 * fosls-contact: frictionless linear elastic contact (Signorini's problem)
 * in first-order system least-squares form, solved by a monotone multilevel
 * method.
 *
 *   fosls-contact SCENE [--set "Section/Name=value" ...]
 *   mpirun -np N fosls-contact SCENE [...]
 *   fosls-contact --print-parameters [SCENE [--set ...]] | --help | --version
 *
 * main() reads the command line and the scene (CommandLine,
 * ParameterReader) and hands the parameters to FoslsProblem. Exit codes
 * (ExitCode): 0 converged, 1 error (one line on stderr, no
 * output files), 2 not converged (files written, one line on stderr), 3 an
 * error on some of several processes that the others did not learn of
 * (one line, MPI_Abort, ErrorLine::stop): the program decides the errors
 * it expects on all processes (CollectiveError), so 3 means memory that
 * ran out on one process, or a defect.
 */
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>

#include <fosls_contact/base/collective_error.h>
#include <fosls_contact/base/error_line.h>
#include <fosls_contact/base/interruption.h>
#include <fosls_contact/input/command_line.h>
#include <fosls_contact/input/parameter_reader.h>
#include <fosls_contact/input/same_input.h>
#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/problem/fosls_problem.h>

#include <muParser.h>

#include <malloc.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    /**
     * Restore glibc's use of mmap and the trimming of the heap, which
     * SuperLU_DIST (which deal.II's Trilinos brings) turns off when it is
     * loaded (mallopt(M_MMAP_MAX, 0), mallopt(M_TRIM_THRESHOLD, -1) in its
     * library constructor). Without it every array comes from the heap and a
     * freed one stays with the process, so a run holds the transients of its
     * assembly to the end (doc/performance.md, section 5). Blocks of 32 MB
     * and more (glibc's largest dynamic threshold) are mapped and unmapped
     * again; smaller ones stay on the heap, whose top is returned above
     * 64 MB (twice the threshold, as glibc does).
     */
    void
    restore_malloc_behaviour()
    {
      mallopt(M_MMAP_MAX, 65536);
      mallopt(M_MMAP_THRESHOLD, 32 << 20);
      mallopt(M_TRIM_THRESHOLD, 64 << 20);
    }


    /**
     * Started without a launcher (mpirun, srun), the process is an MPI
     * singleton that talks to no other. For it Open MPI's MPI_Init spawns a
     * daemon (orted) and loads the PSM/PSM2 transports of its cm layer, most
     * of the time of a small run (doc/performance.md, section 3). The
     * isolated singleton needs no daemon, and the ob1 layer suffices for a
     * process without peers. A launched process keeps Open MPI's choices (a
     * cluster's fabric), and so does a value the user set.
     *
     * Isolated singletons all name their session directory the same
     * (/tmp/ompi.<host>.<uid>/jf.0/1): one process's clean-up in
     * MPI_Finalize could remove it while another's MPI_Init created it,
     * which then failed ("A call to mkdir was unable to create the desired
     * directory"; doc/performance.md, section 3). A process without peers
     * needs none.
     */
    void
    configure_singleton_mpi()
    {
      const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") ||
                            std::getenv("PMI_RANK") || std::getenv("PMI_SIZE") ||
                            std::getenv("PMI_FD") || std::getenv("SLURM_STEP_NUM_TASKS");
      if (!launched)
        {
          setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
          setenv("OMPI_MCA_pml", "ob1", 0);
          setenv("OMPI_MCA_orte_create_session_dirs", "0", 0);
        }
    }


    /**
     * Read the command line and the scene file into @p prm on every
     * process: one that cannot (the file missing on its node, another
     * command line) stops them all with its line (CollectiveError), where
     * the others would wait for it in their first collective call.
     */
    std::unique_ptr<const CommandLine>
    read_input(const int argc, char *argv[], ParameterReader &reader)
    {
      std::unique_ptr<const CommandLine> arguments;
      CollectiveError::run(MPI_COMM_WORLD, [&]() {
        arguments = std::make_unique<const CommandLine>(argc, argv);
        if (arguments->help || arguments->version)
          return;
        if (!arguments->scene.empty())
          reader.read_file(arguments->scene);
        for (const auto &o : arguments->overrides)
          reader.set(o);
      });
      return arguments;
    }


    /**
     * Every process must work on the same input (SameInput): the command
     * line, the scene's values and the mesh file it names. Collective.
     */
    void
    check_same_input(const int                 argc,
                     char *                    argv[],
                     const CommandLine &       command_line,
                     dealii::ParameterHandler &prm)
    {
      SameInput   input;
      std::string command;
      for (int i = 1; i < argc; ++i)
        command += std::string(argv[i]) + '\0';
      input.add("command line", command);
      if (!command_line.help && !command_line.version && !command_line.scene.empty())
        {
          std::ostringstream values;
          prm.print_parameters(values, dealii::ParameterHandler::PRM);
          input.add("scene (its parameter values)", values.str());
          prm.enter_subsection("Geometry");
          const std::string mesh = prm.get("Shape") == "file" ? prm.get("Mesh file") : "";
          prm.leave_subsection();
          if (!mesh.empty())
            {
              std::ifstream      file(mesh, std::ios::binary);
              std::ostringstream bytes;
              bytes << file.rdbuf();
              input.add("mesh file (" + mesh + ")", bytes.str());
            }
        }
      input.check(MPI_COMM_WORLD);
    }


    /**
     * Run the scene read into @p prm: ExitCode::success, or
     * ExitCode::not_converged with its line on stderr.
     */
    int
    run_scene(dealii::ParameterHandler &prm, const bool first_rank)
    {
      Parameters::AllParameters parameters;
      parameters.parse_parameters(prm);
      if (parameters.solver.threads > 0)
        dealii::MultithreadInfo::set_thread_limit(parameters.solver.threads);
      std::ostringstream used;
      prm.print_parameters(used, dealii::ParameterHandler::PRM);
      const std::string not_converged = parameters.geometry.dimension == 2 ?
                                          FoslsProblem<2>(parameters, used.str()).run() :
                                          FoslsProblem<3>(parameters, used.str()).run();
      if (not_converged.empty())
        return ExitCode::success;
      if (first_rank)
        ErrorLine::print("fosls-contact: " + not_converged +
                         "; the output files are written, summary.json has "
                         "\"converged\": false");
      return ExitCode::not_converged;
    }
  } // namespace
} // namespace FoslsContact


int
main(int argc, char *argv[])
{
  using namespace FoslsContact;
  restore_malloc_behaviour();
  configure_singleton_mpi();
  // threads: as many as cores (or DEAL_II_NUM_THREADS) until the scene's
  // Solver/Threads says otherwise
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv,
                                               dealii::numbers::invalid_unsigned_int);
  // a closed stdout (`fosls-contact scene.prm | head -1`) must not kill the
  // run before its files are written: writes to it then fail quietly (after
  // MPI_Init, which may install its own handler)
  std::signal(SIGPIPE, SIG_IGN);
  // a time limit's SIGTERM or a Ctrl-C: the run stops with what it
  // finished (exit code 4)
  Interruption::install();
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();

  MPI_Comm error_comm;
  MPI_Comm_dup(MPI_COMM_WORLD, &error_comm);
  const bool  first_rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::string where      = "command line";
  int         status     = ExitCode::success;
  try
    {
      dealii::ParameterHandler prm;
      Parameters::AllParameters::declare_parameters(prm);
      ParameterReader reader(prm);
      const std::unique_ptr<const CommandLine> arguments = read_input(argc, argv, reader);
      const CommandLine &                      command_line = *arguments;
      check_same_input(argc, argv, command_line, prm);
      if (command_line.help || command_line.version)
        {
          if (first_rank)
            std::cout << (command_line.help ? CommandLine::help_text() :
                                              CommandLine::version_text());
        }
      else
        {
          if (command_line.print_parameters)
            {
              // every parameter with its value, default, pattern and
              // documentation, as JSON (scripts/make_parameter_doc.py)
              if (first_rank)
                prm.print_parameters(std::cout, dealii::ParameterHandler::JSON);
            }
          else
            {
              where = command_line.scene;
              status = run_scene(prm, first_rank);
            }
        }
    }
  catch (const InterruptedRun &exc)
    {
      // (every process throws it at once: Interruption::requested() is
      // collective)
      if (first_rank)
        ErrorLine::print("fosls-contact: " + ErrorLine::one_line(exc.what()));
      MPI_Comm_free(&error_comm);
      return ExitCode::interrupted;
    }
  catch (const InputError &exc)
    {
      return ErrorLine::stop("fosls-contact: error in " + ErrorLine::one_line(exc.where()) +
                               ": " + ErrorLine::one_line(exc.what()),
                             error_comm);
    }
  catch (const std::exception &exc)
    {
      return ErrorLine::stop("fosls-contact: error in " + ErrorLine::one_line(where) + ": " +
                               ErrorLine::text(exc),
                             error_comm);
    }
  catch (const mu::ParserError &exc)
    {
      // muparser's exceptions are no std::exception
      return ErrorLine::stop("fosls-contact: error in " + ErrorLine::one_line(where) +
                               ": expression parser: " + ErrorLine::one_line(exc.GetMsg()),
                             error_comm);
    }
  catch (...)
    {
      return ErrorLine::stop("fosls-contact: error in " + ErrorLine::one_line(where) +
                               ": unknown error",
                             error_comm);
    }
  MPI_Comm_free(&error_comm);
  return status;
}
