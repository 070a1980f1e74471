#pragma once
/// Output directories: checked before a command's work starts (so that an unwritable --out fails
/// at once, with nothing written) and created when the first file goes in.
#include <string>

namespace tecido::io {

/// Checks, creating nothing, that directory `dir` could receive files: it is a writable
/// directory, or its nearest existing ancestor is one. Throws OutputError naming `dir` and the
/// obstacle ("/dev/null is not a directory", "Permission denied", "Read-only file system").
void check_output_dir(const std::string& dir);

/// Creates `dir` and its missing parents; throws OutputError naming `dir` and the obstacle.
void create_output_directories(const std::string& dir);

}  // namespace tecido::io
