#include <fosls_contact/output/directory_swap.h>
#include <fosls_contact/output/file_system.h>
#include <fosls_contact/output/output_directory.h>

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <vector>

namespace FoslsContact
{
  namespace fs = std::filesystem;

  void
  DirectorySwap::replace(const fs::path &             directory,
                         const fs::path &             staging,
                         const std::set<std::string> &names,
                         const std::set<std::string> &old_listed,
                         const std::string &          parameter)
  {
    const auto fail = [&](const std::string &what) {
      throw std::runtime_error(parameter + ": " + what);
    };
    const std::string &manifest_name = OutputDirectory::manifest_name;
    const fs::path parent     = directory.parent_path();
    const bool     has_old    = FileSystem::present(directory);
    // the user's files: hard links into the new directory now, directories
    // (and what cannot be linked) moved after the swap
    std::vector<std::string> to_move;
    for (const auto &name : has_old ? FileSystem::list(directory) : std::vector<std::string>())
      {
        if (name == manifest_name || old_listed.count(name))
          continue;
        mode_t mode = 0;
        FileSystem::present(directory / name, &mode);
        if (names.count(name))
          {
            if (S_ISDIR(mode))
              fail("cannot replace the directory " + FileSystem::quoted(directory / name) +
                   " by the output file of that name");
            continue;
          }
        if (S_ISDIR(mode) ||
            ::linkat(AT_FDCWD, (directory / name).c_str(), AT_FDCWD, (staging / name).c_str(), 0) != 0)
          to_move.push_back(name);
      }
    // the new directory keeps the old one's permissions
    struct stat old_status;
    if (has_old && ::stat(directory.c_str(), &old_status) == 0)
      ::chmod(staging.c_str(), old_status.st_mode & 07777);
    std::string error = FileSystem::sync(staging);
    if (!error.empty())
      fail("cannot sync " + FileSystem::quoted(staging) + ": " + error);

    fs::path old;
    if (!has_old)
      {
        if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, directory.c_str(), RENAME_NOREPLACE) != 0 &&
            ((errno != EINVAL && errno != ENOSYS && errno != EOPNOTSUPP) ||
             ::rename(staging.c_str(), directory.c_str()) != 0))
          fail("cannot rename " + FileSystem::quoted(staging) + " to it: " + FileSystem::system_error(errno));
      }
    else if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, directory.c_str(), RENAME_EXCHANGE) == 0)
      old = staging;
    else if (errno == EINVAL || errno == ENOSYS || errno == EOPNOTSUPP)
      {
        // no atomic exchange on this filesystem: two renames
        old = parent / ("." + directory.filename().string() + ".staging-" +
                        std::to_string(::getpid()) + "-old");
        if (::rename(directory.c_str(), old.c_str()) != 0)
          fail("cannot move the old directory aside: " + FileSystem::system_error(errno));
        if (::rename(staging.c_str(), directory.c_str()) != 0)
          {
            const int e = errno;
            ::rename(old.c_str(), directory.c_str());
            fail("cannot rename " + FileSystem::quoted(staging) + " to it: " + FileSystem::system_error(e));
          }
      }
    else
      fail("cannot exchange " + FileSystem::quoted(staging) + " with it: " + FileSystem::system_error(errno));
    FileSystem::sync(parent);

    // the old directory: move the user's directories over, remove what a
    // run wrote (its list, and the outputs replaced) and the links carried
    if (old.empty())
      return;
    for (const auto &name : to_move)
      ::rename((old / name).c_str(), (directory / name).c_str());
    for (const auto &name : FileSystem::list(old))
      {
        mode_t mode = 0;
        if (!FileSystem::present(old / name, &mode) || S_ISDIR(mode))
          continue;
        if (name == manifest_name || old_listed.count(name) || names.count(name) ||
            FileSystem::same_file(old / name, directory / name))
          ::unlink((old / name).c_str());
      }
    ::rmdir(old.c_str());
    FileSystem::sync(parent);
  }
} // namespace FoslsContact
