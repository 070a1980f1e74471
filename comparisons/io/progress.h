#pragma once
/// A progress bar on stderr for long sweeps:
///   label [############..................] 12/72  0.85/s  ETA 1:10
/// redrawn in place with '\r' at most about five times a second, and only when stderr is a
/// terminal (isatty(2)); silent otherwise, so logs and tests see nothing. finish() (or the
/// destructor) draws the final state and ends the line.
#include <chrono>
#include <cstddef>
#include <mutex>
#include <ostream>
#include <string>

namespace tecido::io {

class Progress {
 public:
  /// Draws on std::cerr when stderr is a terminal.
  Progress(std::size_t total, std::string label);
  /// Draws on `out` when `enabled` (for tests), with no rate limit.
  Progress(std::size_t total, std::string label, std::ostream& out, bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Counts `n` more items done; safe to call from several threads.
  void tick(std::size_t n = 1);
  /// Draws the final state and a newline (once; further calls do nothing).
  void finish();

  /// The bar line for `done` of `total` after `seconds` (no '\r'): exposed for tests.
  static std::string line(const std::string& label, std::size_t done, std::size_t total, double seconds);

 private:
  void draw_locked(bool force);

  std::size_t total_;
  std::string label_;
  std::ostream* out_;
  bool enabled_;
  bool rate_limited_;
  bool finished_ = false;
  std::size_t done_ = 0;
  std::size_t last_width_ = 0;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

}  // namespace tecido::io
