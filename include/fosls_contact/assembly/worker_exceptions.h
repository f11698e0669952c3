#ifndef fosls_contact_assembly_worker_exceptions_h
#define fosls_contact_assembly_worker_exceptions_h

#include <fosls_contact/base/collective_error.h>

#include <mpi.h>

#include <exception>
#include <mutex>

namespace FoslsContact
{
  /**
   * The first exception thrown in the workers of a WorkStream loop, kept
   * to be thrown after it. An exception that leaves a worker aborts the
   * program (deal.II prints it and calls std::abort); a bad expression met
   * in a cell loop, e.g. an obstacle normal that evaluates to zero, must
   * end in the usual one-line error instead.
   */
  class WorkerExceptions
  {
  public:
    /** Calls @p work(); keeps what it throws if nothing was kept before. */
    template <typename Work>
    void
    guard(const Work &work)
    {
      try
        {
          work();
        }
      catch (...)
        {
          std::lock_guard<std::mutex> lock(mutex);
          if (!error)
            error = std::current_exception();
        }
    }

    /** Whether a worker threw. */
    bool
    caught() const
    {
      return static_cast<bool>(error);
    }

    /** Throws the kept exception, if any (after the loop). */
    void
    rethrow() const
    {
      if (error)
        std::rethrow_exception(error);
    }

    /**
     * Throws, on every process of @p comm, the kept exception of the first
     * process that kept one (CollectiveError): a loop over a process's own
     * cells meets an expression's error at its points only, and the other
     * processes must not go on into the next collective call alone.
     */
    void
    rethrow(const MPI_Comm comm) const
    {
      CollectiveError::run(comm, [this]() { rethrow(); });
    }

  private:
    std::mutex         mutex;
    std::exception_ptr error;
  };
} // namespace FoslsContact

#endif
