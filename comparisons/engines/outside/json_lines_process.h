#pragma once
/// A child process spoken to in lines: started once with `/bin/sh -c COMMAND` in its own process
/// group, one request line written to its standard input, one reply line read from its standard
/// output, its standard error kept (the last few KB) for messages. Every round trip has a deadline
/// and a size: a child that dies, closes its output, answers more than one line, has not finished
/// its reply line by the timeout or writes more than io::kMaxReplyBytes without a newline is killed (its whole process group) and the round trip throws ProcessFailure with what
/// happened and the tail of its stderr; every later round trip throws the same.
///
/// One request at a time: round_trip() holds a mutex, so threads take turns (the answers do not
/// depend on the order). The destructor closes the child's input, gives it a moment to exit, then
/// kills its process group; no child outlives the object.
#include "comparisons/io/limits.h"

#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <sys/types.h>

namespace tecido::outside {

/// A failed round trip: what() is the problem ("exited with status 3", "no reply within 2 s", ...);
/// stderr_tail() the child's last stderr output, on one line.
class ProcessFailure : public std::runtime_error {
 public:
  ProcessFailure(const std::string& problem, std::string tail) : std::runtime_error(problem), tail_(std::move(tail)) {}
  const std::string& stderr_tail() const { return tail_; }

 private:
  std::string tail_;
};

class JsonLinesProcess {
 public:
  /// Starts `command`; throws ProcessFailure when it cannot be started. A round trip fails past
  /// `timeout` for the whole reply, or past `max_reply_bytes` without a newline.
  JsonLinesProcess(std::string command, std::chrono::duration<double> timeout,
                   std::size_t max_reply_bytes = io::kMaxReplyBytes);
  ~JsonLinesProcess();
  JsonLinesProcess(const JsonLinesProcess&) = delete;
  JsonLinesProcess& operator=(const JsonLinesProcess&) = delete;

  /// Writes `request` and a newline, returns the reply line without its newline. `seconds`, when
  /// given, receives the round trip's wall time from this thread's turn on (waiting excluded). The
  /// first round trip may take kStartupAllowance when that is longer than the timeout: it includes
  /// the child's start-up (an interpreter loading its modules on a busy machine).
  std::string round_trip(const std::string& request, double* seconds = nullptr);
  static constexpr double kStartupAllowance = 10.0;  ///< [s]

  const std::string& command() const { return command_; }
  /// Round trips so far (reports quote the door's cost).
  long long round_trips() const;

 private:
  void write_all(const std::string& data, std::chrono::steady_clock::time_point deadline,
                 std::chrono::duration<double> limit);
  std::string read_line(std::chrono::steady_clock::time_point deadline, std::chrono::duration<double> limit);
  /// The failure of a reply not finished by the deadline: none of it, or part of it.
  std::string late_reply(std::chrono::duration<double> limit, const std::string& allowance) const;
  /// Reads what the child wrote on stderr without blocking.
  void drain_stderr();
  /// Kills the child, records `problem` and throws it.
  [[noreturn]] void fail(const std::string& problem);
  /// "exited with status N" / "killed by signal S" after the child ended (waits for it).
  std::string exit_description();
  std::string tail_line() const;

  std::string command_;
  std::chrono::duration<double> timeout_;
  std::size_t max_reply_bytes_;
  pid_t pid_ = -1;
  int in_ = -1, out_ = -1, err_ = -1;  ///< our ends: the child's stdin, stdout, stderr
  std::string pending_;                ///< bytes read past the last reply's newline
  std::string err_tail_;
  std::string failure_;                ///< set once the child failed; later round trips rethrow it
  bool reaped_ = false;
  int status_ = 0;
  long long round_trips_ = 0;
  mutable std::mutex mutex_;
};

}  // namespace tecido::outside
