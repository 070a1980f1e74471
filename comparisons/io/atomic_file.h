#pragma once
/// Writing results so that a killed or failed run never leaves a half-written file: the content
/// goes to a new temporary file in the same directory, which is then renamed over the target.
#include <string>

namespace tecido::io {

/// Writes `content` to `path` atomically (temporary file + rename), creating parent directories.
/// Throws OutputError naming the path on any failure (a directory that cannot be created, a file
/// that cannot be opened or written, a full disk, a failed rename); the temporary file is removed
/// and the target left as it was.
void write_file_atomic(const std::string& path, const std::string& content);

/// Writes `content` into the existing or new file `path` (truncated first), checking every write
/// and the close; throws OutputError naming `path` (e.g. "/dev/full: cannot write: No space left
/// on device"). Not atomic: write_file_atomic's building block.
void write_whole_file(const std::string& path, const std::string& content);

}  // namespace tecido::io
