#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <fosls_contact/base/collective_error.h>

namespace FoslsContact
{
  using namespace dealii;


  void
  CollectiveError::decide(const MPI_Comm     comm,
                          const bool         failed,
                          const std::string &error,
                          const std::string &where)
  {
    const unsigned int n_processes = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int first =
      n_processes == 1 ?
        (failed ? 0 : 1) :
        Utilities::MPI::min(failed ? Utilities::MPI::this_mpi_process(comm) : n_processes, comm);
    if (first == n_processes)
      return;
    const std::string text =
      n_processes == 1 ? error : Utilities::MPI::broadcast(comm, error, first);
    const std::string place =
      n_processes == 1 ? where : Utilities::MPI::broadcast(comm, where, first);
    if (!place.empty())
      throw InputError(place, text);
    AssertThrow(false, ExcMessage(text));
  }
} // namespace FoslsContact
