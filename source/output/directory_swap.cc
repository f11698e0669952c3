#include <fosls_contact/base/error_line.h>
#include <fosls_contact/base/file_system.h>
#include <fosls_contact/output/directory_swap.h>
#include <fosls_contact/output/output_directory.h>

#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace FoslsContact
{
  namespace fs = std::filesystem;

  const std::string DirectorySwap::record_name = ".fosls-contact-staging";

  namespace
  {
    /** A directory's device and inode: what it is, whatever its name. */
    struct Identity
    {
      dev_t device = 0;
      ino_t inode  = 0;
      bool  valid  = false;

      bool
      operator==(const Identity &other) const
      {
        return valid && other.valid && device == other.device && inode == other.inode;
      }
    };

    Identity
    identity(const fs::path &path)
    {
      struct stat status;
      Identity    id;
      if (::lstat(path.c_str(), &status) == 0)
        id = {status.st_dev, status.st_ino, true};
      return id;
    }

    std::string
    text(const Identity &id)
    {
      return std::to_string(id.device) + " " + std::to_string(id.inode);
    }

    /** What the record of @p directory says (nothing valid if it has none). */
    struct Record
    {
      bool     present = false;
      Identity self, replaces;
      /** The process id of the run, in the names it gives (empty if unknown). */
      std::string pid;

      explicit Record(const fs::path &directory)
      {
        std::ifstream in(directory / DirectorySwap::record_name);
        present = bool(in);
        std::string line;
        while (std::getline(in, line))
          {
            std::istringstream words(line);
            std::string        a, b;
            Identity           id;
            if (!(words >> a))
              continue;
            if (a == "fosls-contact" && words >> b && b == "staging" && words >> id.device >> id.inode)
              {
                self = {id.device, id.inode, true};
                if (!(words >> pid) || pid.find_first_not_of("0123456789") != std::string::npos)
                  pid.clear();
              }
            else if (a == "replaces" && words >> id.device >> id.inode)
              replaces = {id.device, id.inode, true};
          }
      }

      /**
       * Whether the record says that @p directory is an unpublished staging
       * directory: it describes @p directory itself, or it is incomplete
       * (the run was killed while writing it, before any rename).
       */
      bool
      unpublished(const fs::path &directory) const
      {
        return present && (!self.valid || self == identity(directory));
      }
    };

    /** The file names listed in the list `.fosls-contact-files` of @p directory. */
    std::set<std::string>
    read_manifest(const fs::path &directory)
    {
      std::set<std::string> names;
      std::ifstream         in(directory / OutputDirectory::manifest_name);
      std::string           line;
      while (std::getline(in, line))
        if (!line.empty() && line.find('/') == std::string::npos && line != "." && line != "..")
          names.insert(line);
      return names;
    }

    /**
     * The files of @p directory that a run wrote: those its list names or,
     * in a directory without a list, those with the name of an output file.
     */
    std::set<std::string>
    program_files(const fs::path &directory)
    {
      if (FileSystem::present(directory / OutputDirectory::manifest_name))
        return read_manifest(directory);
      std::set<std::string> names;
      for (const auto &name : FileSystem::list(directory))
        if (DirectorySwap::is_output_name(name))
          names.insert(name);
      return names;
    }


    /** The staging directories `.<name>.staging-*` beside @p directory. */
    std::vector<fs::path>
    stagings(const fs::path &directory)
    {
      const std::string     prefix = "." + directory.filename().string() + ".staging-";
      std::vector<fs::path> found;
      for (const auto &entry : FileSystem::list(directory.parent_path()))
        {
          mode_t mode = 0;
          const fs::path path = directory.parent_path() / entry;
          if (entry.rfind(prefix, 0) == 0 && FileSystem::present(path, &mode) && S_ISDIR(mode))
            found.push_back(path);
        }
      return found;
    }

    /**
     * Move the entries of @p from that a run did not write into
     * @p directory and remove the rest: the files named in @p program (a
     * run's output), and those that are already in @p directory (the hard
     * links made before the swap). An entry whose name @p directory
     * already uses for something else stays in @p from (which then stays
     * too): nothing of the user's is removed. The list and the record go
     * last, so that a kill in between leaves a directory that a second
     * call still reads the same way.
     */
    void
    carry_over(const fs::path &from, const fs::path &directory, const std::set<std::string> &program)
    {
      for (const auto &name : FileSystem::list(from))
        {
          if (name == OutputDirectory::manifest_name || name == DirectorySwap::record_name)
            continue;
          const fs::path source = from / name, target = directory / name;
          mode_t         mode   = 0;
          if (!FileSystem::present(source, &mode))
            continue;
          if (!S_ISDIR(mode) && (program.count(name) || FileSystem::same_file(source, target)))
            ::unlink(source.c_str());
          else if (!FileSystem::present(target))
            ::rename(source.c_str(), target.c_str());
        }
      FileSystem::sync(directory);
      ::unlink((from / DirectorySwap::record_name).c_str());
      ::unlink((from / OutputDirectory::manifest_name).c_str());
      ::rmdir(from.c_str());
    }

    /**
     * Remove the staging directory @p staging that was never published:
     * its files are the run's own or hard links to files of the directory;
     * its record goes last. (It has no subdirectories; one that someone
     * put there keeps it, and it stays.)
     */
    void
    remove_unpublished(const fs::path &staging)
    {
      for (const auto &name : FileSystem::list(staging))
        {
          mode_t mode = 0;
          if (name != DirectorySwap::record_name && FileSystem::present(staging / name, &mode) &&
              !S_ISDIR(mode))
            ::unlink((staging / name).c_str());
        }
      ::unlink((staging / DirectorySwap::record_name).c_str());
      ::rmdir(staging.c_str());
    }

    /**
     * Hard links in @p staging to the files of @p directory that no run
     * wrote (not in @p old_listed, not named as the new files @p names);
     * returns their names. Throws if a directory of the user's has the
     * name of a new file.
     */
    std::vector<std::string>
    link_user_files(const fs::path &             directory,
                    const fs::path &             staging,
                    const std::set<std::string> &old_listed,
                    const std::set<std::string> &names,
                    const std::string &          parameter)
    {
      std::vector<std::string> linked;
      for (const auto &entry : FileSystem::list(directory))
        {
          if (entry == OutputDirectory::manifest_name || entry == DirectorySwap::record_name ||
              old_listed.count(entry))
            continue;
          mode_t mode = 0;
          FileSystem::present(directory / entry, &mode);
          if (names.count(entry))
            {
              if (S_ISDIR(mode))
                throw std::runtime_error(parameter + ": cannot replace the directory " +
                                         FileSystem::quoted(directory / entry) +
                                         " by the output file of that name");
              continue;
            }
          if (!S_ISDIR(mode) && ::linkat(AT_FDCWD, (directory / entry).c_str(), AT_FDCWD,
                                         (staging / entry).c_str(), 0) == 0)
            linked.push_back(entry);
        }
      return linked;
    }

    /**
     * Keep the results that cannot be published (what is at the path of
     * @p directory is not the run's to replace) in `<name>.results-<pid>`
     * beside it, without the @p linked files of the user's, and throw
     * @p message with where they are.
     */
    [[noreturn]] void
    keep_results(const fs::path &                directory,
                 const fs::path &                staging,
                 const std::vector<std::string> &linked,
                 const std::string &             message)
    {
      for (const auto &link : linked)
        ::unlink((staging / link).c_str());
      const fs::path kept = directory.parent_path() /
                            (directory.filename().string() + ".results-" + std::to_string(::getpid()));
      if (::rename(staging.c_str(), kept.c_str()) != 0)
        throw std::runtime_error(message + "; the results could not be kept: " +
                                 FileSystem::system_error(errno));
      ::unlink((kept / DirectorySwap::record_name).c_str());
      FileSystem::sync(directory.parent_path());
      throw std::runtime_error(message + "; the results are kept in " + FileSystem::quoted(kept));
    }

    /**
     * The run that made @p record was killed while it undid a swap with
     * something that had taken the place of @p directory just before (see
     * DirectorySwap::replace): that is put back, found under the name the
     * swap gave it (the record names the run's process), and the results
     * are kept in `<name>.results-<pid>`, as the run would have done. With
     * the exchange (@p published: the results are in the place of
     * @p directory) it is exchanged back; with the two renames (nothing is
     * in that place) renamed back.
     */
    void
    restore_displaced(const fs::path &directory, const Record &record, const bool published)
    {
      if (record.pid.empty())
        return;
      const fs::path    parent = directory.parent_path();
      const std::string name   = directory.filename().string();
      const fs::path    aside  = parent / ("." + name + ".staging-" + record.pid + (published ? "" : "-old"));
      if (!FileSystem::present(aside) || Record(aside).unpublished(aside))
        return;
      if (!published)
        {
          ::rename(aside.c_str(), directory.c_str());
          return;
        }
      if (::renameat2(AT_FDCWD, directory.c_str(), AT_FDCWD, aside.c_str(), RENAME_EXCHANGE) != 0)
        return;
      const fs::path kept = parent / (name + ".results-" + record.pid);
      if (::rename(aside.c_str(), kept.c_str()) == 0)
        ::unlink((kept / DirectorySwap::record_name).c_str());
    }

    /** What the file type @p mode is, for messages. */
    std::string
    kind(const mode_t mode)
    {
      if (S_ISREG(mode))
        return "a regular file";
      if (S_ISLNK(mode))
        return "a symbolic link";
      return "a file that is not a directory";
    }
  } // namespace


  bool
  DirectorySwap::locked(const fs::path &path)
  {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0)
      return false;
    struct stat status;
    const bool  held = ::fstat(fd, &status) == 0 && S_ISREG(status.st_mode) &&
                      ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    ::close(fd); // (and with it the shared lock, if it was taken)
    return held;
  }


  bool
  DirectorySwap::is_output_name(const std::string &name)
  {
    // the names OutputDirectory::write is given: Postprocessor (the tables,
    // the summary, contact_NNNN.csv of every adaptive step), VtuOutput (the
    // solution and contact surface of every step, their pieces, the .pvd
    // series), FoslsProblem (adaptive_steps.csv)
    static const std::regex written("(solution|contact_surface)_[0-9]{4,}(\\.[0-9]+\\.vtu|\\.pvtu)|"
                                    "contact(_[0-9]{4,})?\\.csv");
    return name == "solution.pvd" || name == "convergence.csv" || name == "summary.json" ||
           name == "used_parameters.prm" || name == "adaptive_steps.csv" ||
           name == OutputDirectory::manifest_name || std::regex_match(name, written);
  }


  std::string
  DirectorySwap::foreign_entry(const fs::path &directory)
  {
    if (FileSystem::present(directory / OutputDirectory::manifest_name))
      return "";
    for (const auto &entry : FileSystem::list(directory))
      if (!is_output_name(entry) && entry != record_name)
        return entry;
    return "";
  }


  std::string
  DirectorySwap::directory_under_output_name(const fs::path &directory)
  {
    for (const auto &entry : FileSystem::list(directory))
      {
        mode_t mode = 0;
        if (is_output_name(entry) && FileSystem::present(directory / entry, &mode) &&
            S_ISDIR(mode))
          return entry;
      }
    return "";
  }


  int
  DirectorySwap::make_record(const fs::path &staging, const std::string &parameter)
  {
    const fs::path path = staging / record_name;
    const auto     fail = [&](const std::string &what, const int fd) {
      const int error = errno;
      if (fd >= 0)
        ::close(fd);
      throw std::runtime_error(parameter + ": cannot " + what + " " + FileSystem::quoted(path) +
                               ": " + FileSystem::system_error(error));
    };
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      fail("create", fd);
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
      fail("lock", fd);
    const std::string line =
      "fosls-contact staging " + text(identity(staging)) + " " + std::to_string(::getpid()) + "\n";
    if (::write(fd, line.data(), line.size()) != static_cast<ssize_t>(line.size()) ||
        ::fsync(fd) != 0)
      fail("write", fd);
    return fd;
  }


  void
  DirectorySwap::discard(const fs::path &staging)
  {
    if (Record(staging).unpublished(staging))
      remove_unpublished(staging);
  }


  void
  DirectorySwap::recover(const fs::path &directory, const std::string &parameter)
  {
    const fs::path parent = directory.parent_path();
    for (const auto &staging : stagings(directory))
      if (locked(staging / record_name))
        throw std::runtime_error(parameter + ": another run of fosls-contact writes into it (its "
                                 "staging directory " + FileSystem::quoted(staging) +
                                 " is in use); wait for it or choose another directory");
    if (locked(directory / record_name))
      throw std::runtime_error(parameter + ": another run of fosls-contact publishes its files "
                               "there; wait for it or choose another directory");

    // a publication killed after the new directory took the place of the
    // old one: the old one's entries are carried over
    if (FileSystem::present(directory / record_name))
      {
        const Record record(directory);
        bool         found = false;
        if (record.self == identity(directory))
          for (const auto &old : stagings(directory))
            if (identity(old) == record.replaces)
              {
                auto program = program_files(old);
                for (const auto &name : read_manifest(directory))
                  program.insert(name);
                carry_over(old, directory, program);
                found = true;
              }
        if (!found && record.self == identity(directory) && record.replaces.valid)
          restore_displaced(directory, record, true);
        ::unlink((directory / record_name).c_str());
        FileSystem::sync(directory);
      }

    // killed between the two renames (no exchange): the old directory,
    // aside, goes back
    if (!FileSystem::present(directory))
      for (const auto &staging : stagings(directory))
        {
          const Record record(staging);
          if (!record.unpublished(staging) || !record.replaces.valid)
            continue;
          for (const auto &old : stagings(directory))
            if (identity(old) == record.replaces)
              ::rename(old.c_str(), directory.c_str());
          if (!FileSystem::present(directory))
            restore_displaced(directory, record, false);
        }

    // staging directories that were never published are removed; what
    // else has a staging name (no record) is treated as an old directory
    for (const auto &staging : stagings(directory))
      {
        if (Record(staging).unpublished(staging))
          remove_unpublished(staging);
        else if (FileSystem::present(directory))
          carry_over(staging, directory, program_files(staging));
        else
          ::rmdir(staging.c_str()); // (only if empty: killed before its record was made)
      }
    FileSystem::sync(parent);
  }


  void
  DirectorySwap::replace(const fs::path &             directory,
                         const fs::path &             staging,
                         const int                    record_fd,
                         const std::set<std::string> &names,
                         const std::string &          parameter)
  {
    const auto fail = [&](const std::string &what) {
      throw std::runtime_error(parameter + ": " + what);
    };
    const fs::path    parent = directory.parent_path();
    const std::string name   = directory.filename().string();
    const std::string pid    = std::to_string(::getpid());
    std::vector<std::string> linked;
    const auto               keep = [&](const std::string &what) {
      keep_results(directory, staging, linked, parameter + ": " + what);
    };

    // what is at the path now must be what the run may replace: it may
    // have changed since the run began
    mode_t     mode    = 0;
    const bool has_old = FileSystem::present(directory, &mode);
    if (has_old && !S_ISDIR(mode))
      keep("has become " + kind(mode) + " during the run, which the program does not replace");
    if (has_old && !foreign_entry(directory).empty())
      keep("has become a directory that holds '" + ErrorLine::quote(foreign_entry(directory)) +
           "', which fosls-contact did not write, during the run; the program does not replace it");
    if (has_old && !directory_under_output_name(directory).empty())
      keep("has come to hold a directory '" +
           ErrorLine::quote(directory_under_output_name(directory)) +
           "' under the name of an output file during the run; the program does not "
           "replace it");
    const Identity              old_id = identity(directory);
    const std::set<std::string> old_listed =
      has_old ? program_files(directory) : std::set<std::string>();

    // the user's files: hard links into the new directory now, the rest
    // (directories) moved after the swap
    if (has_old)
      linked = link_user_files(directory, staging, old_listed, names, parameter);
    // the new directory keeps the old one's permissions
    struct stat old_status;
    if (has_old && ::stat(directory.c_str(), &old_status) == 0)
      ::chmod(staging.c_str(), old_status.st_mode & 07777);
    std::string error = FileSystem::sync(staging);
    if (!error.empty())
      fail("cannot sync " + FileSystem::quoted(staging) + ": " + error);
    // the record says which directory the new one replaces
    if (has_old)
      {
        const std::string line = "replaces " + text(old_id) + "\n";
        if (::lseek(record_fd, 0, SEEK_END) < 0 ||
            ::write(record_fd, line.data(), line.size()) != static_cast<ssize_t>(line.size()) ||
            ::fsync(record_fd) != 0)
          fail("cannot write " + FileSystem::quoted(staging / record_name) + ": " +
               FileSystem::system_error(errno));
      }

    // the rename that publishes, and a check that it replaced the directory
    // the record names (if the path changed in between, it is undone)
    const auto no_exchange = [] { return errno == EINVAL || errno == ENOSYS || errno == EOPNOTSUPP; };
    const std::string changed = "was replaced by something else during the run, which the "
                                "program does not replace";
    fs::path old;
    if (!has_old)
      {
        if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, directory.c_str(), RENAME_NOREPLACE) != 0 &&
            (!no_exchange() || ::rename(staging.c_str(), directory.c_str()) != 0))
          {
            if (errno == EEXIST || errno == ENOTEMPTY || errno == ENOTDIR || errno == EISDIR)
              keep("has come into existence during the run, and the program does not replace it");
            fail("cannot rename " + FileSystem::quoted(staging) + " to it: " + FileSystem::system_error(errno));
          }
      }
    else if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, directory.c_str(), RENAME_EXCHANGE) == 0)
      {
        old = staging;
        if (!(identity(old) == old_id))
          {
            if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, directory.c_str(), RENAME_EXCHANGE) != 0)
              fail(changed + "; it is now " + FileSystem::quoted(staging));
            keep(changed);
          }
      }
    else if (no_exchange())
      {
        // no atomic exchange on this filesystem: two renames
        old = parent / ("." + name + ".staging-" + pid + "-old");
        if (::rename(directory.c_str(), old.c_str()) != 0)
          fail("cannot move the old directory aside: " + FileSystem::system_error(errno));
        if (!(identity(old) == old_id))
          {
            if (::rename(old.c_str(), directory.c_str()) != 0)
              fail(changed + "; it is now " + FileSystem::quoted(old));
            keep(changed);
          }
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

    // the old directory: the user's entries move over, the rest goes
    if (!old.empty())
      {
        auto program = old_listed;
        program.insert(names.begin(), names.end());
        carry_over(old, directory, program);
      }
    ::unlink((directory / record_name).c_str());
    FileSystem::sync(directory);
    FileSystem::sync(parent);
  }
} // namespace FoslsContact
