#include <deal.II/base/mpi.h>

#include <fosls_contact/base/interruption.h>

#include <csignal>

namespace FoslsContact
{
  namespace
  {
    /** The first signal noted (0: none). */
    volatile std::sig_atomic_t noted = 0;

    extern "C" void
    note_signal(const int signal)
    {
      if (noted == 0)
        noted = signal;
      // (a second signal takes the default action: the process ends)
      std::signal(signal, SIG_DFL);
    }
  } // namespace


  void
  Interruption::install()
  {
    std::signal(SIGTERM, note_signal);
    std::signal(SIGINT, note_signal);
  }


  bool
  Interruption::requested(const MPI_Comm comm)
  {
    return dealii::Utilities::MPI::max(noted != 0 ? 1 : 0, comm) != 0;
  }


  std::string
  Interruption::signal_name()
  {
    return noted == SIGTERM ? "SIGTERM" : noted == SIGINT ? "SIGINT" : "";
  }
} // namespace FoslsContact
