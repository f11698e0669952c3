#include <deal.II/base/mpi.h>

#include <fosls_contact/output/collective_error.h>
#include <fosls_contact/output/directory_swap.h>
#include <fosls_contact/output/error_line.h>
#include <fosls_contact/output/file_system.h>
#include <fosls_contact/output/output_directory.h>

#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace FoslsContact
{
  namespace fs = std::filesystem;

  const std::string OutputDirectory::manifest_name = ".fosls-contact-files";

  namespace
  {

    /** The file names listed in the manifest of @p directory. */
    std::set<std::string>
    read_manifest(const fs::path &directory)
    {
      std::set<std::string> names;
      std::ifstream         in(directory / OutputDirectory::manifest_name);
      std::string           line;
      while (std::getline(in, line))
        if (!line.empty() && line.find('/') == std::string::npos && line != "." &&
            line != "..")
          names.insert(line);
      return names;
    }

    /** Whether @p name is the name of a file the program writes. */
    bool
    is_output_name(const std::string &name)
    {
      static const std::regex piece("solution_0000\\.[0-9]+\\.vtu");
      return name == "contact.csv" || name == "convergence.csv" || name == "summary.json" ||
             name == "used_parameters.prm" || name == "solution_0000.pvtu" ||
             name == OutputDirectory::manifest_name || std::regex_match(name, piece);
    }
  } // namespace


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
    {
      std::error_code error;
      const fs::path  current = fs::current_path(error);
      const fs::path  target  = fs::weakly_canonical(directory, error);
      if (!error && std::mismatch(target.begin(), target.end(), current.begin(),
                                  current.end()).first == target.end())
        fail("contains the current directory; name a directory of its own");
    }
    const fs::path parent = directory.parent_path();
    const std::string name = directory.filename().string();

    // the parent directories: existing ones must be directories, missing
    // ones are made (and removed again if the run publishes nothing)
    std::vector<fs::path> missing;
    for (fs::path p = parent; !p.empty(); p = p.parent_path())
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
    if (FileSystem::present(directory, &mode))
      {
        struct stat status;
        if (::stat(directory.c_str(), &status) != 0 || !S_ISDIR(status.st_mode))
          fail("exists and is not a directory");
        if (::access(directory.c_str(), R_OK | W_OK | X_OK) != 0)
          fail("cannot be read and written: " + FileSystem::system_error(errno));
        // the results are published by renaming a staging directory in
        // its place, which a mount point refuses (EBUSY): found here, not
        // after the computation
        struct stat above;
        if (::stat(parent.c_str(), &above) == 0 && above.st_dev != status.st_dev)
          fail("is a mount point, which the program cannot replace by its results (it "
               "renames a directory in its place); name a directory inside it");
        // the run replaces the directory: only one it wrote (its list is
        // there), or one that holds nothing but output files (an earlier
        // version's), never someone's other directory (/tmp, a home)
        if (!FileSystem::present(directory / manifest_name))
          for (const auto &entry : FileSystem::list(directory))
            if (!is_output_name(entry) && entry.rfind(".staging-", 0) != 0)
              fail("exists and holds '" + ErrorLine::quote(entry) +
                   "', which fosls-contact did not write (the directory has no " +
                   manifest_name + "); name a new or empty directory, or one "
                   "fosls-contact wrote");
      }

    // the lock: a second run into the directory fails here, at once. The
    // lock file is removed when the run ends, so after locking it must
    // still be the file of that name.
    lock_path = parent / ("." + name + ".lock");
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
        struct stat held, named;
        if (::fstat(lock_fd, &held) == 0 && ::lstat(lock_path.c_str(), &named) == 0 &&
            held.st_dev == named.st_dev && held.st_ino == named.st_ino)
          break;
        ::close(lock_fd);
        lock_fd = -1;
      }

    // staging directories of runs that were killed
    const std::string stale_prefix = "." + name + ".staging-";
    for (const auto &entry : FileSystem::list(parent))
      if (entry.rfind(stale_prefix, 0) == 0)
        clean_stale(parent / entry);

    staging = parent / (stale_prefix + std::to_string(::getpid()));
    if (::mkdir(staging.c_str(), 0777) != 0)
      fail("cannot make the staging directory " + FileSystem::quoted(staging) + ": " + FileSystem::system_error(errno));
  }


  void
  OutputDirectory::clean_stale(const fs::path &stale) const
  {
    // only what the program wrote: the files it lists or names, and the
    // hard links of files carried over (the same file is in the directory)
    const auto listed = read_manifest(stale);
    for (const auto &name : FileSystem::list(stale))
      {
        mode_t mode = 0;
        if (!FileSystem::present(stale / name, &mode) || S_ISDIR(mode))
          continue;
        if (listed.count(name) || is_output_name(name) || FileSystem::same_file(stale / name, directory / name))
          ::unlink((stale / name).c_str());
      }
    ::rmdir(stale.c_str());
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
    DirectorySwap::replace(directory,
                           staging,
                           names,
                           FileSystem::present(directory) ? read_manifest(directory) : std::set<std::string>(),
                           parameter());
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
      {
        std::error_code error;
        fs::remove_all(staging, error);
      }
    if (lock_fd >= 0)
      {
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
