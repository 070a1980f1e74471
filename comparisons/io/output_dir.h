#pragma once
/// Output directories: checked before a command's work starts (so that an unwritable --out fails
/// at once, with nothing written), created when the first file goes in, and written by one run at
/// a time (OutputDirLock).
#include <string>

namespace tecido::io {

/// Checks, creating nothing, that directory `dir` could receive files: it is a writable
/// directory, or its nearest existing ancestor is one. Throws OutputError naming `dir` and the
/// obstacle ("/dev/null is not a directory", "Permission denied", "Read-only file system").
void check_output_dir(const std::string& dir);

/// Creates `dir` and its missing parents; throws OutputError naming `dir` and the obstacle.
/// Then takes every OutputDirLock of this process whose directory now exists (see there).
void create_output_directories(const std::string& dir);

/// One run's claim on its output directory, for the object's life, so that two runs writing into
/// one --out at once never mix their files: the second refuses with OutputError "DIR: another
/// tecido run (pid N) is writing into this directory; ..." (the CLI's one line, exit code 2).
/// The claim is an exclusive, non-blocking flock(2) on the directory itself (no lock file: the
/// directory holds only the run's outputs), taken at construction when the directory exists, and
/// otherwise when create_output_directories first creates it, that is before the run's first
/// file goes in; a refusal then comes at that point, with nothing of this run written. The
/// other run's pid is read from /proc/locks. The kernel drops the lock when the process ends,
/// however it ends (no stale lock after a crash). Construct it after check_output_dir: it
/// creates nothing.
class OutputDirLock {
 public:
  explicit OutputDirLock(std::string dir);
  ~OutputDirLock();
  OutputDirLock(const OutputDirLock&) = delete;
  OutputDirLock& operator=(const OutputDirLock&) = delete;

  /// Takes the lock if the directory exists and it is not yet taken; throws as described above.
  void take_if_present();
  bool held() const { return fd_ >= 0; }

 private:
  std::string dir_;
  int fd_ = -1;
};

}  // namespace tecido::io
