#pragma once
/// Writing results so that a killed run never leaves a half-written file: the content goes to
/// a temporary file in the same directory, which is then renamed over the target.
#include <string>

namespace tecido::io {

/// Writes `content` to `path` atomically (temporary file + rename). Creates parent
/// directories. Throws std::runtime_error on failure.
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace tecido::io
