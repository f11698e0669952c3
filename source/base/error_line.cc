#include <deal.II/base/exceptions.h>

#include <fosls_contact/base/error_line.h>
#include <fosls_contact/base/exit_code.h>

#include <unistd.h>

#include <chrono>
#include <new>
#include <sstream>
#include <thread>

namespace FoslsContact
{
  namespace
  {
    /**
     * The length of the valid UTF-8 sequence at @p text[i] (1 for ASCII),
     * or 0 if the bytes there are not one.
     */
    std::size_t
    utf8_length(const std::string &text, const std::size_t i)
    {
      const auto byte = [&](const std::size_t k) {
        return static_cast<unsigned char>(text[k]);
      };
      const unsigned char c = byte(i);
      std::size_t         n = 0;
      if (c < 0x80)
        return 1;
      else if (c >= 0xc2 && c <= 0xdf)
        n = 2;
      else if (c >= 0xe0 && c <= 0xef)
        n = 3;
      else if (c >= 0xf0 && c <= 0xf4)
        n = 4;
      else
        return 0;
      if (i + n > text.size())
        return 0;
      for (std::size_t k = 1; k < n; ++k)
        if ((byte(i + k) & 0xc0) != 0x80)
          return 0;
      // no overlong 3- and 4-byte forms, no surrogates, nothing above U+10FFFF
      if ((c == 0xe0 && byte(i + 1) < 0xa0) || (c == 0xed && byte(i + 1) > 0x9f) ||
          (c == 0xf0 && byte(i + 1) < 0x90) || (c == 0xf4 && byte(i + 1) > 0x8f))
        return 0;
      return n;
    }

    std::string
    hex(const unsigned char c)
    {
      static const char digits[] = "0123456789abcdef";
      return std::string("\\x") + digits[c / 16] + digits[c % 16];
    }
  } // namespace


  std::string
  ErrorLine::text(const std::exception &exc)
  {
    std::string text;
    if (const auto *e = dynamic_cast<const dealii::ExceptionBase *>(&exc))
      {
        std::ostringstream info;
        e->print_info(info);
        text = info.str();
        const auto pos = text.find("Additional information:");
        if (pos != std::string::npos)
          text = text.substr(pos + 23);
      }
    else if (dynamic_cast<const std::bad_alloc *>(&exc) != nullptr)
      // (what() says only "std::bad_alloc")
      text = "out of memory (std::bad_alloc): the mesh and solver need more than this process "
             "may allocate; see doc/performance.md for the memory per DoF";
    else
      text = exc.what();
    return one_line(text);
  }


  std::string
  ErrorLine::one_line(const std::string &text)
  {
    std::string out;
    bool        space = false;
    for (std::size_t i = 0; i < text.size();)
      {
        const unsigned char c = text[i];
        if (c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\v' || c == '\f')
          {
            space = !out.empty();
            ++i;
            continue;
          }
        if (space)
          out += ' ';
        space                 = false;
        const std::size_t n   = utf8_length(text, i);
        if (n == 0 || c < 0x20 || c == 0x7f)
          {
            out += hex(c);
            ++i;
          }
        else
          {
            out += text.substr(i, n);
            i += n;
          }
      }
    return out;
  }


  std::string
  ErrorLine::quote(const std::string &text, const std::size_t max_length)
  {
    std::string out;
    for (std::size_t i = 0; i < text.size() && i < max_length;)
      {
        const unsigned char c = text[i];
        const std::size_t   n = utf8_length(text, i);
        if (c == '\n')
          out += "\\n";
        else if (c == '\t')
          out += "\\t";
        else if (n == 0 || c < 0x20 || c == 0x7f)
          out += hex(c);
        else
          {
            out += text.substr(i, n);
            i += n;
            continue;
          }
        ++i;
      }
    if (text.size() > max_length)
      out += "...";
    return out;
  }


  void
  ErrorLine::print(const std::string &line)
  {
    const std::string text = line + "\n";
    std::size_t       done = 0;
    while (done < text.size())
      {
        const ssize_t n = ::write(STDERR_FILENO, text.data() + done, text.size() - done);
        if (n <= 0)
          break;
        done += n;
      }
  }


  int
  ErrorLine::stop(const std::string &line, const MPI_Comm error_comm)
  {
    int n_processes = 1, rank = 0;
    MPI_Comm_size(error_comm, &n_processes);
    MPI_Comm_rank(error_comm, &rank);
    if (n_processes == 1)
      {
        print(line);
        return 1;
      }
    MPI_Request request;
    MPI_Ibarrier(error_comm, &request);
    int        done  = 0;
    const auto start = std::chrono::steady_clock::now();
    while (!done && std::chrono::steady_clock::now() - start < std::chrono::seconds(10))
      {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (!done)
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    if (done)
      {
        if (rank == 0)
          print(line);
        return 1;
      }
    print(line);
    MPI_Abort(MPI_COMM_WORLD, ExitCode::error_on_some_processes);
    return ExitCode::error_on_some_processes;
  }
} // namespace FoslsContact
