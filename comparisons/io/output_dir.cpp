#include "comparisons/io/output_dir.h"

#include "comparisons/io/output_error.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

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

}  // namespace

void check_output_dir(const std::string& dir) {
  if (dir.empty()) throw OutputError(dir, "empty path for an output directory");
  const std::string why = obstacle(dir);
  if (!why.empty()) throw OutputError(dir, "cannot write into this directory: " + why);
}

void create_output_directories(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!ec) return;
  const std::string why = obstacle(dir);
  throw OutputError(dir, "cannot create directory: " + (why.empty() ? ec.message() : why));
}

}  // namespace tecido::io
