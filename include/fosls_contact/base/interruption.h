#ifndef fosls_contact_base_interruption_h
#define fosls_contact_base_interruption_h

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace FoslsContact
{
  /**
   * SIGTERM and SIGINT (a batch system's time limit, Ctrl-C) as a request
   * to stop with what is finished. The handler only notes the signal (all
   * a signal handler may safely do) and restores the default action, so
   * that a second signal ends the process at once. The run asks where it
   * can stop with a consistent result: the solvers' monitor after every
   * iteration, the run between its phases. An adaptive run then publishes
   * the steps it finished (FoslsProblem::run()).
   *
   * Whether a signal arrived is decided by all processes together
   * (requested() is collective): mpirun forwards the signal to every
   * process, but not at the same instant, and a process that stopped alone
   * would leave the others waiting in their next collective call.
   */
  class Interruption
  {
  public:
    /** Install the handlers of SIGTERM and SIGINT (once, in main). */
    static void install();
    /** Whether some process received SIGTERM or SIGINT. Collective. */
    static bool requested(const MPI_Comm comm);
    /** "SIGTERM" or "SIGINT", the first signal this process noted ("" if none). */
    static std::string signal_name();
  };

  /**
   * The run stopped on Interruption::requested(): thrown on every process
   * at once, after the finished steps were published; what() says what
   * was kept. main() exits with ExitCode::interrupted.
   */
  class InterruptedRun : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace FoslsContact

#endif
