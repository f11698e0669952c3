#ifndef fosls_contact_base_collective_error_h
#define fosls_contact_base_collective_error_h

#include <deal.II/base/mpi.h>

#include <fosls_contact/base/error_line.h>
#include <fosls_contact/base/input_error.h>

#include <mpi.h>

#include <exception>
#include <string>

namespace FoslsContact
{
  /**
   * An error that only some processes may meet: a data expression
   * evaluated at points of a process's own cells (an obstacle normal that
   * is zero somewhere), a file that only some processes can read, memory
   * that runs out on the process that gathers a problem. If such a process
   * threw alone, the others would wait in their next collective call until
   * ErrorLine::stop aborts the run, 10 s later, instead of all stopping
   * with one line. Here the processes run their local part, then agree:
   * if any of them failed, every one throws the error of the first (the
   * lowest rank) that failed.
   *
   * The local part must not call a collective operation itself: a process
   * that throws before it would leave the others waiting there.
   */
  class CollectiveError
  {
  public:
    /**
     * Runs @p work() on this process, then throws on every process of
     * @p comm the text of the exception that the work of the first failing
     * process threw (an InputError with its place in the input, any other
     * as a deal.II ExcMessage); returns if none threw. On one process the
     * work's own exception leaves as it is.
     */
    template <typename Work>
    static void
    run(const MPI_Comm comm, const Work &work)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
        {
          work();
          return;
        }
      std::string error, where;
      bool        failed = false;
      try
        {
          work();
        }
      catch (const InputError &exc)
        {
          failed = true;
          error  = exc.what();
          where  = exc.where();
        }
      catch (const std::exception &exc)
        {
          failed = true;
          error  = ErrorLine::text(exc);
        }
      catch (...)
        {
          // (as main() says it: nothing else here throws anything else)
          failed = true;
          error  = "unknown error";
        }
      decide(comm, failed, error, where);
    }

    /**
     * Throws on every process of @p comm the @p error of the first process
     * with @p failed (an InputError at @p where if that is not empty);
     * returns on every process if none failed. A collective call.
     */
    static void
    decide(const MPI_Comm     comm,
           const bool         failed,
           const std::string &error,
           const std::string &where = "");
  };
} // namespace FoslsContact

#endif
