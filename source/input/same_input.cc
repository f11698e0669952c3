#include <deal.II/base/mpi.h>

#include <fosls_contact/base/input_error.h>
#include <fosls_contact/input/same_input.h>

#include <cstdint>

namespace FoslsContact
{
  namespace
  {
    /** FNV-1a, 64 bits: the same on every process and machine (std::hash need not be). */
    unsigned long
    fnv1a(const std::string &text)
    {
      std::uint64_t hash = 14695981039346656037ull;
      for (const unsigned char c : text)
        {
          hash ^= c;
          hash *= 1099511628211ull;
        }
      return hash;
    }
  } // namespace


  void
  SameInput::add(const std::string &what, const std::string &contents)
  {
    names.push_back(what);
    hashes.push_back(fnv1a(contents));
  }


  void
  SameInput::check(const MPI_Comm comm) const
  {
    if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    // (the number of parts first: a process that read fewer parts, e.g.
    // one started with --help, differs there)
    const auto all = dealii::Utilities::MPI::all_gather(comm, hashes);
    // (the first process's names, so that every process says the same)
    const auto first = dealii::Utilities::MPI::broadcast(comm, names, 0);
    for (unsigned int r = 1; r < all.size(); ++r)
      if (all[r] != all[0])
        {
          unsigned int part = 0;
          while (part < all[0].size() && part < all[r].size() && all[r][part] == all[0][part])
            ++part;
          const std::string what = part < first.size() ? first[part] : names.back();
          throw InputError("MPI processes",
                           "process " + std::to_string(r) + " was started with another " + what +
                             " than process 0: every process of a run must have the same "
                             "command line, scene and mesh files");
        }
  }
} // namespace FoslsContact
