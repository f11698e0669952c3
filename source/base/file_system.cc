#include <fosls_contact/base/error_line.h>
#include <fosls_contact/base/file_system.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace FoslsContact
{
  namespace fs = std::filesystem;

  std::string
  FileSystem::quoted(const fs::path &path)
  {
    return "'" + ErrorLine::quote(path.string()) + "'";
  }


  std::string
  FileSystem::system_error(const int error)
  {
    return std::strerror(error);
  }


  std::string
  FileSystem::sync(const fs::path &path)
  {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
      return system_error(errno);
    const int result = ::fsync(fd);
    const int error  = errno;
    ::close(fd);
    return result == 0 ? "" : system_error(error);
  }


  bool
  FileSystem::present(const fs::path &path, mode_t *mode)
  {
    struct stat status;
    if (::lstat(path.c_str(), &status) != 0)
      return false;
    if (mode)
      *mode = status.st_mode;
    return true;
  }


  bool
  FileSystem::same_file(const fs::path &a, const fs::path &b)
  {
    struct stat sa, sb;
    return ::lstat(a.c_str(), &sa) == 0 && ::lstat(b.c_str(), &sb) == 0 &&
           sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  }


  std::vector<std::string>
  FileSystem::list(const fs::path &directory)
  {
    std::vector<std::string> names;
    std::error_code          error;
    for (fs::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error))
      names.push_back(it->path().filename().string());
    return names;
  }
} // namespace FoslsContact
