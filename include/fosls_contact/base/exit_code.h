#ifndef fosls_contact_base_exit_code_h
#define fosls_contact_base_exit_code_h

namespace FoslsContact
{
  /**
   * The exit codes of fosls-contact (documented in CommandLine::help_text()
   * and the README). They live below every folder because the lowest
   * layer decides one of them: ErrorLine::stop() aborts with
   * error_on_some_processes. A namespace, not an enum class: main()
   * returns them as int.
   */
  namespace ExitCode
  {
    enum : int
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
  } // namespace ExitCode
} // namespace FoslsContact

#endif
