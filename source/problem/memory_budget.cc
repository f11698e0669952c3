#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <fosls_contact/problem/memory_budget.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    /** The value in kB of the line "@p key: value kB" of @p file, or -1. */
    double
    kilobytes(const std::string &file, const std::string &key)
    {
      std::ifstream in(file);
      for (std::string line; std::getline(in, line);)
        if (line.rfind(key + ":", 0) == 0)
          return std::atof(line.c_str() + key.size() + 1);
      return -1;
    }

    /** The number in @p file (its first word), or -1 ("max", absent). */
    double
    number_in(const std::string &file)
    {
      std::ifstream in(file);
      std::string   word;
      if (!(in >> word) || word == "max")
        return -1;
      try
        {
          return std::stod(word);
        }
      catch (...)
        {
          return -1;
        }
    }

    std::string
    gigabytes(const double bytes)
    {
      std::ostringstream text;
      text << std::fixed << std::setprecision(bytes < 1e10 ? 2 : 1) << bytes / 1e9 << " GB";
      return text.str();
    }
  } // namespace


  MemoryBudget::MemoryBudget(const unsigned int dim, const bool replicated, const MPI_Comm comm)
    : comm(comm)
    // (bench/scale.py's largest levels, doc/scale_results.md: the square's
    // level 9 and the cube's level 7, less the file-backed pages)
    , per_dof(dim == 2 ? 1730. : 3814.)
    , available(std::numeric_limits<double>::infinity())
    , sharing(replicated ? 1 : Utilities::MPI::n_mpi_processes(comm))
  {
    MPI_Comm node;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    const double on_node = Utilities::MPI::n_mpi_processes(node);
    MPI_Comm_free(&node);
    const auto take = [this](const double bytes, const std::string &what) {
      if (bytes >= 0 && bytes < available)
        {
          available  = bytes;
          limited_by = what;
        }
    };
    const double mem_available = kilobytes("/proc/meminfo", "MemAvailable");
    if (mem_available >= 0)
      take(1024. * mem_available / on_node, "the machine's available memory (MemAvailable)");
    const double cgroup_max = number_in("/sys/fs/cgroup/memory.max");
    const double cgroup_now = number_in("/sys/fs/cgroup/memory.current");
    if (cgroup_max >= 0 && cgroup_now >= 0)
      take(std::max(0., cgroup_max - cgroup_now) / on_node,
           "the control group's memory limit (memory.max)");
    rlimit limit;
    const double virtual_size = kilobytes("/proc/self/status", "VmSize");
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && virtual_size >= 0)
      take(std::max(0., double(limit.rlim_cur) - 1024. * virtual_size),
           "the process's address-space limit (ulimit -v)");
  }


  types::global_dof_index
  MemoryBudget::affordable_dofs() const
  {
    const double own     = available / per_dof * sharing;
    const double all     = Utilities::MPI::min(own, comm);
    const double largest = std::numeric_limits<types::global_dof_index>::max();
    return all >= largest ? types::global_dof_index(largest) : types::global_dof_index(all);
  }


  void
  MemoryBudget::check(const double n_dofs, const std::string &advice) const
  {
    // the process with the least room decides, and its figures are named
    const double need  = per_dof * n_dofs / sharing;
    const double ratio = Utilities::MPI::max(need / available, comm);
    if (ratio <= 1)
      return;
    const unsigned int worst =
      Utilities::MPI::min(need / available == ratio ? Utilities::MPI::this_mpi_process(comm) :
                                                      Utilities::MPI::n_mpi_processes(comm),
                          comm);
    const double      room = Utilities::MPI::broadcast(comm, available, worst);
    const std::string what = Utilities::MPI::broadcast(comm, limited_by, worst);
    std::ostringstream text;
    text << "the run needs about " << gigabytes(per_dof * n_dofs) << " (" << std::fixed
         << std::setprecision(0)
         << n_dofs << " DoFs at " << per_dof << " bytes per DoF";
    if (sharing > 1)
      text << ", shared by " << sharing << " processes";
    text << ") but " << gigabytes(room) << (sharing > 1 ? " per process" : "")
         << " are available (" << what << "): " << advice;
    AssertThrow(false, ExcMessage(text.str()));
  }
} // namespace FoslsContact
