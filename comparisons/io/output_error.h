#pragma once
/// The one error every writer throws when an output cannot be created or written (a file where a
/// directory should be, no permission, a full disk): the path and the problem. The CLI prints
/// "tecido: PATH: problem" as one line and exits 2, as for bad input (docs/design.md section 3).
#include <stdexcept>
#include <string>

namespace tecido::io {

class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& path, const std::string& problem)
      : std::runtime_error(path + ": " + problem), path_(path), problem_(problem) {}
  const std::string& path() const { return path_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string path_, problem_;
};

}  // namespace tecido::io
