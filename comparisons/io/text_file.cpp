#include "comparisons/io/text_file.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace tecido::io {

namespace {

std::string too_big_message() {
  return "larger than the limit of " + std::to_string(kMaxInputBytes) + " bytes (" +
         std::to_string(kMaxInputBytes >> 20) + " MiB) for an input file";
}

/// Reads fd to its end, at most kMaxInputBytes + 1 bytes; `expected` is a size hint.
std::string read_bounded(int fd, const std::string& path, std::size_t expected) {
  std::string text;
  text.reserve(expected);
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) return text;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw FileError(path, std::string("read error: ") + std::strerror(errno));
    }
    if (text.size() + static_cast<std::size_t>(n) > kMaxInputBytes) throw FileError(path, too_big_message());
    text.append(buf, static_cast<std::size_t>(n));
  }
}

}  // namespace

std::string read_text_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw FileError(path, "no such file");
  if (fs::is_directory(st)) throw FileError(path, "is a directory, not a file");
  std::size_t expected = 0;
  if (fs::is_regular_file(st)) {
    const auto size = fs::file_size(path, ec);
    if (!ec && size > kMaxInputBytes) throw FileError(path, too_big_message());
    if (!ec) expected = static_cast<std::size_t>(size);
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw FileError(path, std::string("cannot be opened for reading: ") + std::strerror(errno));
  try {
    std::string text = read_bounded(fd, path, expected);
    ::close(fd);
    return text;
  } catch (...) {
    ::close(fd);
    throw;
  }
}

}  // namespace tecido::io
