#pragma once
/// Writing results so that a killed or failed run never leaves a half-written file: the content
/// goes to a new temporary file in the same directory, which is flushed to the disk (fsync) and
/// then renamed over the target, and the directory is flushed after the rename. A crash of the
/// process or of the machine at any point leaves the old file or the new one, never an empty or
/// partial one (without the first fsync, a file system may commit the rename before the data).
#include <string>

namespace tecido::io {

/// Writes `content` to `path` atomically (temporary file, fsync, rename, fsync of the directory),
/// creating parent directories. Throws OutputError naming the path on any failure (a directory
/// that cannot be created, a file that cannot be opened, written or synced, a full disk, a failed
/// rename); the temporary file is removed and the target left as it was. A failed sync of the
/// directory after the rename throws too (the new file is in place, but may not survive a crash).
void write_file_atomic(const std::string& path, const std::string& content);

/// Writes `content` into the existing or new file `path` (truncated first), checking every write
/// and the close; throws OutputError naming `path` (e.g. "/dev/full: cannot write: No space left
/// on device"). Not atomic: write_file_atomic's building block.
void write_whole_file(const std::string& path, const std::string& content);

}  // namespace tecido::io
