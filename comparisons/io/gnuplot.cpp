#include "comparisons/io/gnuplot.h"

#include "comparisons/io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace tecido::io {

namespace {

/// Runs `gnuplot FILE` in `dir`, output and errors discarded; true when it exits with 0.
bool run_gnuplot_process(const std::string& dir, const std::string& file) {
  const pid_t pid = ::fork();
  if (pid < 0) return false;
  if (pid == 0) {
    const int null_fd = ::open("/dev/null", O_RDWR);
    if (null_fd < 0 || ::chdir(dir.c_str()) != 0) ::_exit(127);
    ::dup2(null_fd, 0);
    ::dup2(null_fd, 1);
    ::dup2(null_fd, 2);
    ::execlp("gnuplot", "gnuplot", file.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/// True when the file ends with an SVG's closing tag (gnuplot does not always report a failed write).
bool complete_svg(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return false;
  const std::streamoff size = in.tellg();
  const std::streamoff tail = size < 64 ? size : 64;
  std::string end(static_cast<std::size_t>(tail), '\0');
  in.seekg(size - tail);
  in.read(end.data(), tail);
  return in && end.find("</svg>") != std::string::npos;
}

}  // namespace

bool gnuplot_available() {
  static const bool found = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  return found;
}

bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script) {
  write_file_atomic(dir + "/" + name + ".gp", script);
  if (!gnuplot_available()) return false;
  const std::string tag = ".tmp." + std::to_string(::getpid());
  const std::string output = "set output '" + name + ".svg'";
  std::string redirected = script;
  const auto at = redirected.find(output);
  if (at != std::string::npos) redirected.replace(at, output.size(), "set output '" + name + ".svg" + tag + "'");
  const std::string run_script = name + ".gp" + tag;
  write_file_atomic(dir + "/" + run_script, redirected);
  bool ok = run_gnuplot_process(dir, run_script);
  std::remove((dir + "/" + run_script).c_str());
  if (at == std::string::npos) return ok;
  const std::string svg = dir + "/" + name + ".svg";
  ok = ok && complete_svg(svg + tag) && std::rename((svg + tag).c_str(), svg.c_str()) == 0;
  std::remove((svg + tag).c_str());
  return ok;
}

}  // namespace tecido::io
