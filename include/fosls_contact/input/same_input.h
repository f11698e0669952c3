#ifndef fosls_contact_input_same_input_h
#define fosls_contact_input_same_input_h

#include <mpi.h>

#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * Every process of an MPI run must work on the same input. Processes
   * started with different command lines (`mpirun -np 1 fosls-contact A :
   * -np 1 fosls-contact B`, or `--help` on one of them) or reading
   * different files under the same name (a scene or mesh file that differs
   * between nodes) would run different computations and meet in different
   * collective calls: they wait there for ever, or run to exit code 0 on
   * inconsistent data. The processes compare a fingerprint of what they
   * read, its parts in order, and all stop with one line naming the first
   * part that differs and the processes.
   */
  class SameInput
  {
  public:
    /** Add a part of the input, named @p what in the message (e.g. "command line"). */
    void add(const std::string &what, const std::string &contents);
    /**
     * Throw InputError on every process if some process's parts differ
     * from the first process's. Collective.
     */
    void check(const MPI_Comm comm) const;

  private:
    std::vector<std::string>   names;
    std::vector<unsigned long> hashes;
  };
} // namespace FoslsContact

#endif
