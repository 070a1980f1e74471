#include "comparisons/engines/outside/json_lines_process.h"

#include "comparisons/io/escaped_text.h"
#include "comparisons/io/limits.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace tecido::outside {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kTailBytes = 4096;        ///< stderr kept
constexpr std::size_t kTailShown = 600;         ///< of which messages show the last

/// Writing to a child that has exited must be an EPIPE error, not a signal that kills tecido.
void ignore_sigpipe() {
  static std::once_flag once;
  std::call_once(once, [] { std::signal(SIGPIPE, SIG_IGN); });
}

void set_nonblocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

int millis_until(Clock::time_point deadline) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return ms <= 0 ? 0 : static_cast<int>(std::min<long long>(ms, 1 << 30));
}

std::string seconds_text(std::chrono::duration<double> d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g s", d.count());
  return buf;
}

/// Spawns /bin/sh -c command with the three pipes as its stdio, in a new process group.
pid_t spawn(const std::string& command, int in[2], int out[2], int err[2]) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, in[0], 0);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  posix_spawn_file_actions_adddup2(&fa, err[1], 2);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none, def;
  sigemptyset(&none);
  sigemptyset(&def);
  sigaddset(&def, SIGPIPE);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &def);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  const char* argv[] = {"sh", "-c", command.c_str(), nullptr};
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, "/bin/sh", &fa, &attr, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) throw ProcessFailure(std::string("cannot start /bin/sh: ") + std::strerror(rc), "");
  return pid;
}

}  // namespace

JsonLinesProcess::JsonLinesProcess(std::string command, std::chrono::duration<double> timeout,
                                   std::size_t max_reply_bytes)
    : command_(std::move(command)), timeout_(timeout), max_reply_bytes_(max_reply_bytes) {
  ignore_sigpipe();
  int in[2], out[2], err[2];
  if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0)
    throw ProcessFailure(std::string("cannot make pipes: ") + std::strerror(errno), "");
  try {
    pid_ = spawn(command_, in, out, err);
  } catch (...) {
    for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) ::close(fd);
    throw;
  }
  ::close(in[0]);
  ::close(out[1]);
  ::close(err[1]);
  in_ = in[1];
  out_ = out[0];
  err_ = err[0];
  for (int fd : {in_, out_, err_}) set_nonblocking(fd);
}

JsonLinesProcess::~JsonLinesProcess() {
  if (in_ >= 0) ::close(in_);  // end of input: a well-behaved child exits
  if (!reaped_) {
    const auto until = Clock::now() + std::chrono::seconds(2);
    while (!reaped_ && Clock::now() < until) {
      if (::waitpid(pid_, &status_, WNOHANG) == pid_) reaped_ = true;
      else std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  ::kill(-pid_, SIGKILL);  // the group: a shell's children too
  if (!reaped_) ::waitpid(pid_, &status_, 0);
  if (out_ >= 0) ::close(out_);
  if (err_ >= 0) ::close(err_);
}

long long JsonLinesProcess::round_trips() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return round_trips_;
}

std::string JsonLinesProcess::round_trip(const std::string& request, double* seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto start = Clock::now();
  if (!failure_.empty()) throw ProcessFailure(failure_, tail_line());
  // Output nobody asked for (a second line to the previous request) would answer this one.
  for (pollfd fd{out_, POLLIN, 0}; ::poll(&fd, 1, 0) == 1 && (fd.revents & POLLIN);) {
    char buf[4096];
    const ssize_t r = ::read(out_, buf, sizeof buf);
    if (r <= 0) break;
    pending_.append(buf, static_cast<std::size_t>(r));
  }
  if (!pending_.empty()) fail("answered more than one line to the previous request");
  const std::chrono::duration<double> limit =
      round_trips_ == 0 ? std::max(timeout_, std::chrono::duration<double>(kStartupAllowance)) : timeout_;
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(limit);
  write_all(request + "\n", deadline, limit);
  std::string line = read_line(deadline, limit);
  ++round_trips_;
  if (seconds) *seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return line;
}

void JsonLinesProcess::write_all(const std::string& data, Clock::time_point deadline,
                                 std::chrono::duration<double> limit) {
  std::size_t done = 0;
  while (done < data.size()) {
    pollfd fds[2] = {{in_, POLLOUT, 0}, {err_, POLLIN, 0}};
    const int n = ::poll(fds, err_ >= 0 ? 2 : 1, millis_until(deadline));
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) fail("did not read its request within " + seconds_text(limit));
    if (err_ >= 0 && fds[1].revents) drain_stderr();
    if (fds[0].revents & (POLLERR | POLLHUP)) fail("stopped reading its input: " + exit_description());
    if (!(fds[0].revents & POLLOUT)) continue;
    const ssize_t w = ::write(in_, data.data() + done, data.size() - done);
    if (w > 0) done += static_cast<std::size_t>(w);
    else if (errno == EPIPE) fail("stopped reading its input: " + exit_description());
    else if (errno != EAGAIN && errno != EINTR) fail(std::string("write failed: ") + std::strerror(errno));
  }
}

std::string JsonLinesProcess::read_line(Clock::time_point deadline, std::chrono::duration<double> limit) {
  const std::string allowance = round_trips_ == 0 ? " (start-up allowance)" : " (--engine-timeout)";
  // The deadline bounds the whole reply, not the silence between its bytes; the newline is looked
  // for in new bytes only, so a long reply costs its length once.
  for (std::size_t scanned = 0;;) {
    const std::size_t nl = pending_.find('\n', scanned);
    if (nl != std::string::npos) {
      std::string line = pending_.substr(0, nl);
      pending_.erase(0, nl + 1);
      return line;
    }
    scanned = pending_.size();
    if (pending_.size() > max_reply_bytes_)
      fail("a reply longer than the limit of " + std::to_string(max_reply_bytes_ >> 20) + " MiB (kMaxReplyBytes)");
    if (Clock::now() >= deadline) fail(late_reply(limit, allowance));
    pollfd fds[2] = {{out_, POLLIN, 0}, {err_, POLLIN, 0}};
    const int n = ::poll(fds, err_ >= 0 ? 2 : 1, millis_until(deadline));
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) fail(late_reply(limit, allowance));
    if (err_ >= 0 && fds[1].revents) drain_stderr();
    if (!fds[0].revents) continue;
    char buf[65536];
    const ssize_t r = ::read(out_, buf, sizeof buf);
    if (r > 0) pending_.append(buf, static_cast<std::size_t>(r));
    else if (r == 0) fail((pending_.empty() ? "closed its output" : "closed its output mid-line") +
                          std::string(" without a reply: ") + exit_description());
    else if (errno != EAGAIN && errno != EINTR) fail(std::string("read failed: ") + std::strerror(errno));
  }
}

std::string JsonLinesProcess::late_reply(std::chrono::duration<double> limit, const std::string& allowance) const {
  if (pending_.empty()) return "no reply within " + seconds_text(limit) + allowance;
  return "no whole reply within " + seconds_text(limit) + allowance + ": " + std::to_string(pending_.size()) +
         " bytes without a newline by then";
}

void JsonLinesProcess::drain_stderr() {
  char buf[4096];
  for (;;) {
    const ssize_t r = ::read(err_, buf, sizeof buf);
    if (r > 0) {
      err_tail_.append(buf, static_cast<std::size_t>(r));
      if (err_tail_.size() > kTailBytes) err_tail_.erase(0, err_tail_.size() - kTailBytes);
      continue;
    }
    if (r == 0) {  // the child closed stderr: stop polling it
      ::close(err_);
      err_ = -1;
    }
    return;
  }
}

std::string JsonLinesProcess::exit_description() {
  // Give a child that is exiting a moment to finish, so the message names its status.
  const auto until = Clock::now() + std::chrono::milliseconds(1000);
  while (!reaped_ && Clock::now() < until) {
    if (::waitpid(pid_, &status_, WNOHANG) == pid_) reaped_ = true;
    else std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (!reaped_) return "still running";
  if (WIFEXITED(status_)) return "exited with status " + std::to_string(WEXITSTATUS(status_));
  if (WIFSIGNALED(status_)) return std::string("killed by signal ") + std::to_string(WTERMSIG(status_)) + " (" +
                                   ::strsignal(WTERMSIG(status_)) + ")";
  return "ended";
}

void JsonLinesProcess::fail(const std::string& problem) {
  ::kill(-pid_, SIGKILL);
  if (!reaped_) {
    ::waitpid(pid_, &status_, 0);
    reaped_ = true;
  }
  if (err_ >= 0) {
    // The group is dead: read what it left on stderr (bounded: the pipe is at EOF or empty).
    set_nonblocking(err_);
    drain_stderr();
  }
  failure_ = problem;
  throw ProcessFailure(problem, tail_line());
}

std::string JsonLinesProcess::tail_line() const {
  std::string t = err_tail_;
  while (!t.empty() && (t.back() == '\n' || t.back() == '\r' || t.back() == ' ')) t.pop_back();
  if (t.size() > kTailShown) t = "..." + t.substr(t.size() - kTailShown);
  // Lines joined by " | ", everything else the child wrote shown as text (io::escaped_text).
  std::string out;
  for (std::size_t start = 0; start <= t.size();) {
    const std::size_t nl = std::min(t.find('\n', start), t.size());
    out += (start == 0 ? "" : " | ") + io::escaped_text(std::string_view(t).substr(start, nl - start));
    start = nl + 1;
  }
  return out;
}

}  // namespace tecido::outside
