#include <deal.II/base/mpi.h>

#include <fosls_contact/base/collective_error.h>
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
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace FoslsContact
{
  namespace fs = std::filesystem;

  const std::string OutputDirectory::manifest_name = ".fosls-contact-files";

  OutputDirectory::OutputDirectory(const std::string &directory, const MPI_Comm comm)
    : given(directory)
    , comm(comm)
    , first(dealii::Utilities::MPI::this_mpi_process(comm) == 0)
  {
    // (the first process prepares the directory; every process stops on
    // its error)
    CollectiveError::run(comm, [&]() {
      if (first)
        try
          {
            prepare();
          }
        catch (...)
          {
            release();
            throw;
          }
    });
    staging = dealii::Utilities::MPI::broadcast(comm, staging.string(), 0);
  }


  std::string
  OutputDirectory::parameter() const
  {
    return "parameter 'Output/Directory' = '" + ErrorLine::quote(given) + "'";
  }


  void
  OutputDirectory::prepare()
  {
    resolve();
    // (a refused run makes no parent directories inside the other run's
    // directory; the check after the lock is the one that cannot miss it)
    check_nesting();
    make_parents();
    mode_t mode = 0;
    if (FileSystem::present(directory, &mode) && !S_ISDIR(mode))
      throw std::runtime_error(parameter() + ": exists and is not a directory");
    lock();
    check_nesting();
    // what runs that were killed left: finished or undone, before the
    // directory is judged
    DirectorySwap::recover(directory, parameter());
    check_existing();

    staging = directory.parent_path() /
              ("." + directory.filename().string() + ".staging-" + std::to_string(::getpid()));
    if (::mkdir(staging.c_str(), 0777) != 0)
      {
        const int      error = errno;
        const fs::path path  = staging;
        staging.clear(); // (not this run's to remove)
        throw std::runtime_error(parameter() + ": cannot make the staging directory " +
                                 FileSystem::quoted(path) + ": " + FileSystem::system_error(error));
      }
    try
      {
        record_fd = DirectorySwap::make_record(staging, parameter());
      }
    catch (...)
      {
        ::unlink((staging / DirectorySwap::record_name).c_str());
        ::rmdir(staging.c_str());
        staging.clear();
        throw;
      }
  }


  void
  OutputDirectory::resolve()
  {
    const auto fail = [&](const std::string &what) {
      throw std::runtime_error(parameter() + ": " + what);
    };
    directory = fs::absolute(given).lexically_normal();
    if (directory.filename().empty())
      directory = directory.parent_path();
    if (directory == directory.root_path())
      fail("the root directory cannot be an output directory");
    mode_t mode = 0;
    if (FileSystem::present(directory, &mode) && S_ISLNK(mode))
      {
        // the files go where the link points
        std::error_code error;
        directory = fs::canonical(directory, error);
        if (error)
          fail("a symbolic link to nothing (" + error.message() + ")");
      }
    // the swap moves the directory: not the one the run works in
    std::error_code error;
    const fs::path  current = fs::current_path(error);
    const fs::path  target  = fs::weakly_canonical(directory, error);
    if (!error &&
        std::mismatch(target.begin(), target.end(), current.begin(), current.end()).first == target.end())
      fail("contains the current directory; name a directory of its own");
  }


  void
  OutputDirectory::make_parents()
  {
    // existing parent directories must be directories, missing ones are
    // made (and removed again if the run publishes nothing)
    const auto fail = [&](const std::string &what) {
      throw std::runtime_error(parameter() + ": " + what);
    };
    std::vector<fs::path> missing;
    for (fs::path p = directory.parent_path(); !p.empty(); p = p.parent_path())
      {
        struct stat status;
        if (::stat(p.c_str(), &status) == 0)
          {
            if (!S_ISDIR(status.st_mode))
              fail(FileSystem::quoted(p) + " is not a directory");
            break;
          }
        if (errno != ENOENT)
          fail("cannot reach " + FileSystem::quoted(p) + ": " + FileSystem::system_error(errno));
        missing.push_back(p);
        if (p == p.parent_path())
          break;
      }
    for (auto p = missing.rbegin(); p != missing.rend(); ++p)
      {
        if (::mkdir(p->c_str(), 0777) != 0)
          fail("cannot make the directory " + FileSystem::quoted(*p) + ": " + FileSystem::system_error(errno));
        made.push_back(*p);
      }
  }


  void
  OutputDirectory::lock()
  {
    // a second run into the directory fails here, at once. The lock file
    // is removed when the run ends, so after locking it must still be the
    // file of that name.
    const auto fail = [&](const std::string &what) {
      throw std::runtime_error(parameter() + ": " + what);
    };
    lock_path = directory.parent_path() / ("." + directory.filename().string() + ".lock");
    for (;;)
      {
        lock_fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (lock_fd < 0)
          fail("cannot create the lock file " + FileSystem::quoted(lock_path) + ": " + FileSystem::system_error(errno));
        if (::flock(lock_fd, LOCK_EX | LOCK_NB) != 0)
          {
            const int error = errno;
            ::close(lock_fd);
            lock_fd = -1;
            if (error == EWOULDBLOCK)
              fail("another run of fosls-contact writes into it (lock file " +
                   FileSystem::quoted(lock_path) + "); wait for it or choose another directory");
            fail("cannot lock " + FileSystem::quoted(lock_path) + ": " + FileSystem::system_error(error));
          }
        if (held_is_named())
          break;
        ::close(lock_fd);
        lock_fd = -1;
      }
  }


  bool
  OutputDirectory::held_is_named() const
  {
    struct stat held, named;
    return ::fstat(lock_fd, &held) == 0 && ::lstat(lock_path.c_str(), &named) == 0 &&
           held.st_dev == named.st_dev && held.st_ino == named.st_ino;
  }


  void
  OutputDirectory::check_nesting() const
  {
    // Each run holds its lock from before this check to its end, so of two
    // runs, one into a directory inside the other's, the later one finds
    // the other's lock: above its directory, or inside it.
    const std::string advice = "; wait for it or choose a directory outside it";
    for (fs::path p = directory.parent_path(); p.has_filename(); p = p.parent_path())
      {
        const fs::path other = p.parent_path() / ("." + p.filename().string() + ".lock");
        if (DirectorySwap::locked(other))
          throw std::runtime_error(parameter() + ": lies inside " + FileSystem::quoted(p) +
                                   ", the output directory of a run of fosls-contact that is "
                                   "still running (lock file " + FileSystem::quoted(other) + ")" +
                                   advice);
      }
    mode_t mode = 0;
    if (!FileSystem::present(directory, &mode) || !S_ISDIR(mode))
      return;
    std::error_code error;
    for (fs::recursive_directory_iterator
           it(directory, fs::directory_options::skip_permission_denied, error), end;
         !error && it != end; it.increment(error))
      {
        const std::string name = it->path().filename().string();
        if (name.size() > 6 && name.front() == '.' && name.compare(name.size() - 5, 5, ".lock") == 0 &&
            DirectorySwap::locked(it->path()))
          throw std::runtime_error(parameter() + ": holds " +
                                   FileSystem::quoted(it->path().parent_path() /
                                                      name.substr(1, name.size() - 6)) +
                                   ", the output directory of a run of fosls-contact that is "
                                   "still running (lock file " + FileSystem::quoted(it->path()) +
                                   ")" + advice);
      }
  }


  void
  OutputDirectory::check_existing() const
  {
    const auto fail = [&](const std::string &what) {
      throw std::runtime_error(parameter() + ": " + what);
    };
    struct stat status;
    if (::lstat(directory.c_str(), &status) != 0)
      return;
    if (!S_ISDIR(status.st_mode))
      fail("exists and is not a directory");
    if (::access(directory.c_str(), R_OK | W_OK | X_OK) != 0)
      fail("cannot be read and written: " + FileSystem::system_error(errno));
    // the results are published by renaming a staging directory in its
    // place, which a mount point refuses (EBUSY): found here, not after the
    // computation
    struct stat above;
    if (::stat(directory.parent_path().c_str(), &above) == 0 && above.st_dev != status.st_dev)
      fail("is a mount point, which the program cannot replace by its results (it "
           "renames a directory in its place); name a directory inside it");
    // the run replaces the directory: only one it wrote (its list is
    // there), or one that holds nothing but output files (an earlier
    // version's), never someone's other directory (/tmp, a home)
    const std::string entry = DirectorySwap::foreign_entry(directory);
    if (!entry.empty())
      fail("exists and holds '" + ErrorLine::quote(entry) +
           "', which fosls-contact did not write (the directory has no " + manifest_name +
           "); name a new or empty directory, or one fosls-contact wrote");
    // a directory of the user's under an output file's name could neither
    // be carried over beside the new file nor be removed
    const std::string blocking = DirectorySwap::directory_under_output_name(directory);
    if (!blocking.empty())
      fail("holds a directory '" + ErrorLine::quote(blocking) +
           "' under the name of an output file, which the run would write; rename or "
           "move it");
  }


  void
  OutputDirectory::write(const std::string &name,
                         const std::function<void(std::ostream &)> &writer)
  {
    const fs::path path = staging / name;
    const auto     fail = [&](const std::string &what) {
      throw std::runtime_error(parameter() + ": cannot write " + FileSystem::quoted(path) + ": " + what);
    };
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      if (!out)
        fail(FileSystem::system_error(errno));
      errno = 0;
      try
        {
          writer(out);
        }
      catch (const std::exception &e)
        {
          // (deal.II's writers throw on a failed stream: the cause is errno's)
          const int error = errno;
          fail(error ? FileSystem::system_error(error) : ErrorLine::text(e));
        }
      out.flush();
      if (!out)
        fail(errno ? FileSystem::system_error(errno) : "write error");
      out.close();
      if (out.fail())
        fail(errno ? FileSystem::system_error(errno) : "write error");
    }
    const std::string error = FileSystem::sync(path);
    if (!error.empty())
      fail(error);
    written.push_back(name);
  }


  void
  OutputDirectory::publish(const std::string &error)
  {
    // every process has written (and fsynced) its files, or failed
    CollectiveError::decide(comm, !error.empty(), error);
    std::set<std::string> names;
    for (const auto &part : dealii::Utilities::MPI::gather(comm, written, 0))
      names.insert(part.begin(), part.end());
    CollectiveError::run(comm, [&]() {
      if (first)
        publish_here(names);
    });
  }


  void
  OutputDirectory::publish_here(const std::set<std::string> &names)
  {
    write(manifest_name, [&](std::ostream &out) {
      for (const auto &n : names)
        out << n << '\n';
    });
    DirectorySwap::replace(directory, staging, record_fd, names, parameter());
    published = true;
  }


  OutputDirectory::~OutputDirectory()
  {
    release();
  }


  void
  OutputDirectory::release() noexcept
  {
    if (!first)
      return;
    if (!published && !staging.empty())
      DirectorySwap::discard(staging);
    if (record_fd >= 0)
      {
        ::close(record_fd);
        record_fd = -1;
      }
    if (lock_fd >= 0)
      {
        // (only if it is still this run's lock file)
        if (held_is_named())
          ::unlink(lock_path.c_str());
        ::close(lock_fd);
        lock_fd = -1;
      }
    if (!published)
      for (auto p = made.rbegin(); p != made.rend(); ++p)
        ::rmdir(p->c_str());
    made.clear();
    staging.clear();
  }
} // namespace FoslsContact
