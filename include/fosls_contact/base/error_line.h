#ifndef fosls_contact_base_error_line_h
#define fosls_contact_base_error_line_h

#include <mpi.h>

#include <exception>
#include <string>

namespace FoslsContact
{
  /**
   * The one line the program prints on stderr when it stops on an error,
   * `fosls-contact: error in <where>: <what>`, and how it gets there.
   *
   * The text may carry bytes of the user's input (a garbage scene file, a
   * --set value with a newline): they are escaped (`\n`, `\x01`), so the
   * line is one line and sends no control sequence to the terminal.
   * deal.II's exception texts span several lines; they are joined.
   */
  class ErrorLine
  {
  public:
    /**
     * The text of @p exc on one line: deal.II's "additional information"
     * (without its stack trace and source location), or what().
     */
    static std::string text(const std::exception &exc);

    /**
     * @p text with every run of whitespace made one space and every other
     * control byte, and every byte that is not part of valid UTF-8,
     * written as \xNN.
     */
    static std::string one_line(const std::string &text);

    /**
     * A fragment of the user's input for a message: control characters
     * escaped (newline as \n, tab as \t, others as \xNN; invalid UTF-8 as
     * \xNN), at most @p max_length bytes of it (then "...").
     */
    static std::string quote(const std::string &text, const std::size_t max_length = 120);

    /**
     * Print @p line on stderr and return the exit code 1. The line goes to
     * file descriptor 2 directly, not through std::cerr, whose buffer a
     * library may have replaced. With several processes, the processes
     * that fail agree on @p error_comm: if all of them failed (an error
     * every process meets: bad input), the first prints the line; if some
     * did not come within 10 s (an error of one process, the others wait
     * in a collective operation), this one prints its line and aborts the
     * run with exit code 3 (ExitCode::error_on_some_processes; the
     * program decides the errors it expects on all processes,
     * CollectiveError).
     */
    static int stop(const std::string &line, const MPI_Comm error_comm);

    /** Write @p line and a newline to stderr (file descriptor 2). */
    static void print(const std::string &line);
  };
} // namespace FoslsContact

#endif
