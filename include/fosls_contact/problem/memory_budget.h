#ifndef fosls_contact_problem_memory_budget_h
#define fosls_contact_problem_memory_budget_h

#include <deal.II/base/types.h>

#include <mpi.h>

#include <string>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * Whether a run fits into the memory it may use, decided before the
   * memory is taken: a run of more DoFs than the machine holds would
   * otherwise grow until the kernel's out-of-memory killer ends it without
   * a word, after minutes of set-up.
   *
   * The memory a process may use is the least of what the machine has
   * available (MemAvailable of /proc/meminfo, shared by the processes on
   * the node), what its control group leaves (memory.max less
   * memory.current, likewise shared) and what its address-space limit
   * (ulimit -v) leaves. A run needs bytes_per_dof() per DoF of its finest
   * level, the peak memory of the multigrid solver per DoF less the
   * program's file-backed pages, measured on the largest levels that
   * bench/scale.py runs (doc/scale_results.md); the direct solvers need
   * more, which their factorization refuses by its own estimate
   * (SparseDirectSolver). On a partitioned mesh the DoFs are shared by the
   * processes; on a replicated one (adaptive runs) every process holds
   * vectors of all of them.
   */
  class MemoryBudget
  {
  public:
    /** Collective (the processes on each node are counted). */
    MemoryBudget(const unsigned int dim, const bool replicated, const MPI_Comm comm);

    /** The bytes per DoF a run needs (see the class documentation). */
    double bytes_per_dof() const { return per_dof; }
    /** The most DoFs (of all processes) a run fits. */
    types::global_dof_index affordable_dofs() const;
    /**
     * Throw, on every process, a one-line error if a run of @p n_dofs
     * DoFs (all processes; a double: an estimate may exceed the index
     * type) does not fit: the estimate, the memory available and what
     * limits it, and @p advice. Collective.
     */
    void check(const double n_dofs, const std::string &advice) const;

  private:
    MPI_Comm comm;
    double   per_dof;
    /** The bytes this process may use, and what limits them. */
    double      available;
    std::string limited_by;
    /** The processes sharing the DoFs (1 on a replicated mesh). */
    unsigned int sharing;
  };
} // namespace FoslsContact

#endif
