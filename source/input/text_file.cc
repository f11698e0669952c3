#include <fosls_contact/base/error_line.h>
#include <fosls_contact/base/input_error.h>
#include <fosls_contact/input/text_file.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace FoslsContact
{
  std::string
  TextFile::read(const std::string &file, const std::string &what, const std::string &where)
  {
    const std::string name = what + " '" + ErrorLine::quote(file) + "'";
    struct stat       status;
    if (::stat(file.c_str(), &status) != 0)
      {
        const int   error = errno;
        struct stat link;
        if (error == ENOENT && ::lstat(file.c_str(), &link) == 0)
          throw InputError(where, name + " is a symbolic link to a file that does not exist");
        throw InputError(where,
                    name + (error == ENOENT  ? " does not exist" :
                            error == ENOTDIR ? " does not exist: a component of its path "
                                               "is not a directory" :
                            error == EACCES  ? " cannot be reached: permission denied on a "
                                               "directory of its path" :
                                               std::string(" cannot be read: ") +
                                                 std::strerror(error)));
      }
    const auto kind = [](const mode_t mode) {
      return S_ISDIR(mode)  ? "a directory" :
             S_ISFIFO(mode) ? "a FIFO (named pipe), not a regular file" :
             S_ISSOCK(mode) ? "a socket, not a regular file" :
             S_ISCHR(mode)  ? "a character device, not a regular file" :
             S_ISBLK(mode)  ? "a block device, not a regular file" :
                              "not a regular file";
    };
    if (!S_ISREG(status.st_mode))
      throw InputError(where, name + " is " + kind(status.st_mode));
    // (O_NONBLOCK: if the file was replaced by a FIFO since, open() does
    // not wait for a writer; fstat() below finds it)
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
      {
        const int error = errno;
        throw InputError(where,
                    name + " cannot be read: " +
                      (error == EACCES ? std::string("permission denied") :
                                         std::string(std::strerror(error))));
      }
    std::string text;
    if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode))
      {
        ::close(fd);
        throw InputError(where, name + " is " + kind(status.st_mode));
      }
    char buffer[65536];
    for (;;)
      {
        const ssize_t n = ::read(fd, buffer, sizeof(buffer));
        if (n > 0)
          text.append(buffer, n);
        else if (n == 0)
          break;
        else if (errno != EINTR)
          {
            const int error = errno;
            ::close(fd);
            throw InputError(where, name + " cannot be read: " + std::strerror(error));
          }
      }
    ::close(fd);
    return text;
  }
} // namespace FoslsContact
