// A library for LD_PRELOAD that makes the system calls of writing the output
// files fail, kill the process or stop it, for tests/solver/output_*.py:
//
//   FOSLS_FAULT_KILL_AT_RENAME=N  SIGKILL before the N-th rename (rename,
//                                 renameat, renameat2) of the process
//   FOSLS_FAULT_KILL_AT=N         SIGKILL before the N-th call that changes
//                                 a directory's entries (rename, renameat,
//                                 renameat2, link, linkat, unlink, unlinkat,
//                                 rmdir) on a path that contains
//                                 FOSLS_FAULT_PATH (any path if unset)
//   FOSLS_FAULT_STOP_AT=N         SIGSTOP before that N-th call (the test
//                                 changes the files, then sends SIGCONT)
//   FOSLS_FAULT_KILL_AT_WRITE_TO=S  SIGKILL before the first write into a
//                                 file whose path contains S
//   FOSLS_FAULT_NO_EXCHANGE=1     renameat2(..., RENAME_EXCHANGE) fails with
//                                 EINVAL, as on a filesystem without it
//   FOSLS_FAULT_ENOSPC_AFTER=N    writes into files whose path contains
//                                 "staging" fail with ENOSPC once N bytes
//                                 were written into such files
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace
{
  int    renames         = 0;
  int    changes         = 0;
  size_t staging_written = 0;

  template <typename F>
  F
  next(const char *name)
  {
    return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
  }

  void
  before_rename()
  {
    const char *kill_at = std::getenv("FOSLS_FAULT_KILL_AT_RENAME");
    if (kill_at && ++renames == std::atoi(kill_at))
      raise(SIGKILL);
  }

  /**
   * Before a call that changes the entries of a directory, on the paths
   * @p a and @p b (b may be null): the kill or stop of FOSLS_FAULT_KILL_AT
   * and FOSLS_FAULT_STOP_AT.
   */
  void
  before_change(const char *a, const char *b)
  {
    const char *kill_at = std::getenv("FOSLS_FAULT_KILL_AT");
    const char *stop_at = std::getenv("FOSLS_FAULT_STOP_AT");
    if (!kill_at && !stop_at)
      return;
    const char *path = std::getenv("FOSLS_FAULT_PATH");
    if (path && !(a && std::strstr(a, path)) && !(b && std::strstr(b, path)))
      return;
    ++changes;
    if (kill_at && changes == std::atoi(kill_at))
      raise(SIGKILL);
    if (stop_at && changes == std::atoi(stop_at))
      raise(SIGSTOP);
  }

  /** Whether the path of the open file @p fd contains @p part. */
  bool
  path_contains(const int fd, const char *part)
  {
    char link[64], target[4096];
    std::snprintf(link, sizeof(link), "/proc/self/fd/%d", fd);
    const ssize_t length = readlink(link, target, sizeof(target) - 1);
    if (length <= 0)
      return false;
    target[length] = 0;
    return std::strstr(target, part) != nullptr;
  }

  /** Before a write to @p fd: the kill of FOSLS_FAULT_KILL_AT_WRITE_TO. */
  void
  before_write(const int fd)
  {
    const char *part = std::getenv("FOSLS_FAULT_KILL_AT_WRITE_TO");
    if (part && path_contains(fd, part))
      raise(SIGKILL);
  }

  /** Whether a write of @p n bytes to @p fd must fail with ENOSPC. */
  bool
  no_space(const int fd, const size_t n)
  {
    const char *after = std::getenv("FOSLS_FAULT_ENOSPC_AFTER");
    if (!after)
      return false;
    if (!path_contains(fd, "staging"))
      return false;
    if (staging_written + n > static_cast<size_t>(std::atol(after)))
      return true;
    staging_written += n;
    return false;
  }
} // namespace

extern "C"
{
  int
  rename(const char *from, const char *to)
  {
    before_change(from, to);
    before_rename();
    return next<int (*)(const char *, const char *)>("rename")(from, to);
  }

  int
  renameat(int from_fd, const char *from, int to_fd, const char *to)
  {
    before_change(from, to);
    before_rename();
    return next<int (*)(int, const char *, int, const char *)>("renameat")(from_fd, from,
                                                                           to_fd, to);
  }

  int
  renameat2(int from_fd, const char *from, int to_fd, const char *to, unsigned int flags)
  {
    before_change(from, to);
    before_rename();
    if ((flags & RENAME_EXCHANGE) && std::getenv("FOSLS_FAULT_NO_EXCHANGE"))
      {
        errno = EINVAL;
        return -1;
      }
    return next<int (*)(int, const char *, int, const char *, unsigned int)>("renameat2")(
      from_fd, from, to_fd, to, flags);
  }

  int
  link(const char *from, const char *to)
  {
    before_change(from, to);
    return next<int (*)(const char *, const char *)>("link")(from, to);
  }

  int
  linkat(int from_fd, const char *from, int to_fd, const char *to, int flags)
  {
    before_change(from, to);
    return next<int (*)(int, const char *, int, const char *, int)>("linkat")(from_fd, from, to_fd,
                                                                             to, flags);
  }

  int
  unlink(const char *path)
  {
    before_change(path, nullptr);
    return next<int (*)(const char *)>("unlink")(path);
  }

  int
  unlinkat(int fd, const char *path, int flags)
  {
    before_change(path, nullptr);
    return next<int (*)(int, const char *, int)>("unlinkat")(fd, path, flags);
  }

  int
  rmdir(const char *path)
  {
    before_change(path, nullptr);
    return next<int (*)(const char *)>("rmdir")(path);
  }

  ssize_t
  write(int fd, const void *buffer, size_t n)
  {
    before_write(fd);
    if (no_space(fd, n))
      {
        errno = ENOSPC;
        return -1;
      }
    return next<ssize_t (*)(int, const void *, size_t)>("write")(fd, buffer, n);
  }

  ssize_t
  writev(int fd, const struct iovec *vectors, int count)
  {
    size_t n = 0;
    for (int i = 0; i < count; ++i)
      n += vectors[i].iov_len;
    before_write(fd);
    if (no_space(fd, n))
      {
        errno = ENOSPC;
        return -1;
      }
    return next<ssize_t (*)(int, const struct iovec *, int)>("writev")(fd, vectors, count);
  }
}
