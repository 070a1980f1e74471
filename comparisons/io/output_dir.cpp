#include "comparisons/io/output_dir.h"

#include "comparisons/io/output_error.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <vector>

namespace tecido::io {

namespace {

namespace fs = std::filesystem;

/// The nearest ancestor of `dir` (or dir itself) that exists; "." for a relative path none of
/// whose components exists.
fs::path nearest_existing(const fs::path& dir) {
  fs::path p = dir;
  for (;;) {
    std::error_code ec;
    if (fs::exists(fs::status(p, ec))) return p;
    const fs::path up = p.parent_path();
    if (up.empty()) return ".";
    if (up == p) return p;
    p = up;
  }
}

/// Why files cannot go into `dir` (empty when they can): the obstacle on its way.
std::string obstacle(const std::string& dir) {
  const fs::path base = nearest_existing(fs::path(dir));
  std::error_code ec;
  if (!fs::is_directory(fs::status(base, ec))) return base.string() + " is not a directory";
  if (::access(base.c_str(), W_OK | X_OK) != 0) return base.string() + ": " + std::strerror(errno);
  return "";
}

/// The OutputDirLocks of this process not yet taken (their directories did not exist yet).
std::mutex pending_mutex;
std::vector<OutputDirLock*>& pending_locks() {
  static std::vector<OutputDirLock*> locks;
  return locks;
}

/// The pid holding a flock on the file with this device and inode, from /proc/locks (lines like
/// "1: FLOCK  ADVISORY  WRITE 4242 08:01:1234 0 EOF", device numbers in hex), or "unknown".
std::string flock_holder(dev_t dev, ino_t ino) {
  std::ifstream in("/proc/locks");
  std::string line;
  char id[64];
  std::snprintf(id, sizeof id, "%02x:%02x:%llu", major(dev), minor(dev), static_cast<unsigned long long>(ino));
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string num, type, mode, access, pid, where;
    if (!(f >> num >> type)) continue;
    if (type == "->") continue;  // a waiter
    if (f >> mode >> access >> pid >> where && type == "FLOCK" && where == id) return pid;
  }
  return "unknown";
}

}  // namespace

void check_output_dir(const std::string& dir) {
  if (dir.empty()) throw OutputError(dir, "empty path for an output directory");
  const std::string why = obstacle(dir);
  if (!why.empty()) throw OutputError(dir, "cannot write into this directory: " + why);
}

void create_output_directories(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    const std::string why = obstacle(dir);
    throw OutputError(dir, "cannot create directory: " + (why.empty() ? ec.message() : why));
  }
  std::lock_guard<std::mutex> lock(pending_mutex);
  for (OutputDirLock* l : pending_locks()) l->take_if_present();
}

OutputDirLock::OutputDirLock(std::string dir) : dir_(std::move(dir)) {
  {
    std::lock_guard<std::mutex> lock(pending_mutex);
    pending_locks().push_back(this);
  }
  try {
    take_if_present();
  } catch (...) {
    std::lock_guard<std::mutex> lock(pending_mutex);
    auto& v = pending_locks();
    v.erase(std::remove(v.begin(), v.end(), this), v.end());
    throw;
  }
}

OutputDirLock::~OutputDirLock() {
  {
    std::lock_guard<std::mutex> lock(pending_mutex);
    auto& v = pending_locks();
    v.erase(std::remove(v.begin(), v.end(), this), v.end());
  }
  if (fd_ >= 0) ::close(fd_);  // drops the flock
}

void OutputDirLock::take_if_present() {
  if (fd_ >= 0) return;
  const int fd = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT) return;  // not created yet: taken when create_output_directories makes it
    throw OutputError(dir_, std::string("cannot open the directory to lock it: ") + std::strerror(errno));
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    struct stat st {};
    const bool known = ::fstat(fd, &st) == 0;
    ::close(fd);
    if (err != EWOULDBLOCK) throw OutputError(dir_, std::string("cannot lock the directory: ") + std::strerror(err));
    throw OutputError(dir_, "another tecido run (pid " + (known ? flock_holder(st.st_dev, st.st_ino) : "unknown") +
                                ") is writing into this directory; wait for it to end or choose another --out");
  }
  fd_ = fd;
}

}  // namespace tecido::io
