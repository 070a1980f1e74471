#include "comparisons/io/text_file.h"

#include "comparisons/io/input_error.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace tecido::io {

std::string read_text_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InputError(path, "", "no such file");
  if (fs::is_directory(st)) throw InputError(path, "", "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot be opened for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "read error");
  return ss.str();
}

}  // namespace tecido::io
