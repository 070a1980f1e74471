#pragma once
/// The one error every reader throws on bad input: file, location (a JSON pointer such as
/// /particles/3/mass; "line L, column C" for a JSON syntax error, where no value exists to point at;
/// "line N" for text formats) and the problem. The CLI prints what() as
/// one line on stderr and exits 2 (docs/design.md section 3).
#include <stdexcept>
#include <string>

namespace tecido::io {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& where, const std::string& problem)
      : std::runtime_error(file + ": " + (where.empty() ? std::string("/") : where) + ": " + problem),
        file_(file), where_(where), problem_(problem) {}
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, where_, problem_;
};

/// An input file that cannot be read at all (missing, a directory, unreadable, too large;
/// text_file.h): an InputError the CLI prints alike, which the Python module raises as OSError
/// rather than ValueError.
class FileError : public InputError {
 public:
  FileError(const std::string& file, const std::string& problem) : InputError(file, "", problem) {}
};

/// A command-line usage error (unknown engine name, bad option value): exit 2 as well.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tecido::io
