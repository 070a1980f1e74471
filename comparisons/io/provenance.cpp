#include "comparisons/io/provenance.h"

#include "comparisons/io/build_info.h"

namespace tecido::io {

namespace {

std::string& recorded_line() {
  static std::string line;
  return line;
}

/// Characters a POSIX shell takes literally outside quotes.
bool plain_shell_word(const std::string& arg) {
  if (arg.empty()) return false;
  for (unsigned char c : arg) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    std::string("_./:=,+@%-").find(static_cast<char>(c)) != std::string::npos;
    if (!ok) return false;
  }
  return true;
}

std::string shell_quoted(const std::string& arg) {
  if (plain_shell_word(arg)) return arg;
  std::string q = "'";
  for (char c : arg) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

const char* tecido_version() { return TECIDO_BUILD_VERSION; }
const char* tecido_commit() { return TECIDO_BUILD_COMMIT; }

std::string version_line() { return std::string("tecido ") + tecido_version() + " (commit " + tecido_commit() + ")"; }

std::string shell_line(const std::vector<std::string>& args) {
  std::string line;
  for (const std::string& a : args) line += (line.empty() ? "" : " ") + shell_quoted(a);
  return line;
}

void set_command_line(int argc, const char* const* argv) {
  recorded_line() = shell_line(std::vector<std::string>(argv, argv + argc));
}

const std::string& command_line() { return recorded_line(); }

Json provenance_json() {
  return {{"version", tecido_version()}, {"commit", tecido_commit()}, {"command_line", command_line()}};
}

std::string provenance_markdown() {
  return std::string("tecido ") + tecido_version() + ", commit " + tecido_commit() + ": `" + command_line() + "`";
}

}  // namespace tecido::io
