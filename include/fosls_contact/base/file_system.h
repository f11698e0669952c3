#ifndef fosls_contact_base_file_system_h
#define fosls_contact_base_file_system_h

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * The POSIX calls that OutputDirectory needs beside std::filesystem, with
   * errno's text for its messages: fsync of files and directories, lstat
   * (a symbolic link is not followed), the identity of two paths (hard
   * links), and a listing that never throws.
   */
  struct FileSystem
  {
    /** @p path in single quotes, for messages (ErrorLine::quote). */
    static std::string quoted(const std::filesystem::path &path);
    /** The text of errno value @p error. */
    static std::string system_error(const int error);
    /** fsync @p path (a file or a directory); errno's text, or "". */
    static std::string sync(const std::filesystem::path &path);
    /** lstat: whether @p path exists, and its mode. */
    static bool present(const std::filesystem::path &path, mode_t *mode = nullptr);
    /** Whether @p a and @p b are the same file (inode). */
    static bool same_file(const std::filesystem::path &a, const std::filesystem::path &b);
    /** The names in @p directory (none if it cannot be read). */
    static std::vector<std::string> list(const std::filesystem::path &directory);
  };
} // namespace FoslsContact

#endif
