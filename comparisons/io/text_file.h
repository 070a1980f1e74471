#pragma once
/// Reading a whole input file, with the errors every reader reports the same way.
#include <string>

namespace tecido::io {

/// The file's bytes. Throws InputError(path, "", ...) for a missing file, a directory, an
/// unreadable file, a read error, or more than kMaxInputBytes (comparisons/io/limits.h): at
/// most one byte past the limit is read, so a stream without end (/dev/zero) is rejected too.
std::string read_text_file(const std::string& path);

}  // namespace tecido::io
