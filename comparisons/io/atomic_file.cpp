#include "comparisons/io/atomic_file.h"

#include "comparisons/io/output_dir.h"
#include "comparisons/io/output_error.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace tecido::io {

namespace {

std::string errno_text(const char* what) { return std::string(what) + ": " + std::strerror(errno); }

/// Writes every byte to fd; false (errno set) on the first failed write.
bool write_all(int fd, const std::string& content) {
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

/// Creates a new file beside `target` (O_EXCL: never someone else's) and returns its fd and name.
int create_temp_beside(const std::string& target, std::string& name) {
  static std::atomic<unsigned> counter{0};
  for (;;) {
    name = target + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter.fetch_add(1));
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
}

/// Writes every byte to fd, flushes it to the disk when `sync` (fsync), and closes it;
/// OutputError naming `path` if a write, the flush or the close fails (a full disk may show
/// only at the flush or the close).
void write_and_close(int fd, const std::string& path, const std::string& content, bool sync) {
  const char* what = "cannot write";
  bool ok = write_all(fd, content);
  if (ok && sync && ::fsync(fd) != 0) {
    ok = false;
    what = "cannot flush to the disk (fsync)";
  }
  const int first_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!ok) errno = first_errno;
  if (!ok || !closed) throw OutputError(path, errno_text(what));
}

/// Flushes the directory holding `path` (its entries: the rename), so that the new name survives
/// a crash. File systems that cannot sync a directory (EINVAL) are left as they are.
void sync_parent_directory(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string dir = parent.empty() ? "." : parent.string();
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw OutputError(path, errno_text("cannot open its directory to sync it"));
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL;
  const int sync_errno = errno;
  ::close(fd);
  errno = sync_errno;
  if (!ok) throw OutputError(path, errno_text("cannot sync its directory"));
}

}  // namespace

void write_whole_file(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw OutputError(path, errno_text("cannot open for writing"));
  write_and_close(fd, path, content, false);
}

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::filesystem::path target(path);
  if (target.has_parent_path()) create_output_directories(target.parent_path().string());
  std::string tmp;
  const int fd = create_temp_beside(path, tmp);
  if (fd < 0) throw OutputError(path, errno_text("cannot create a file"));
  try {
    write_and_close(fd, path, content, true);
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string problem = errno_text("cannot replace the file");
    ::unlink(tmp.c_str());
    throw OutputError(path, problem);
  }
  sync_parent_directory(path);
}

}  // namespace tecido::io
