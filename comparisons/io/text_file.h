#pragma once
/// Reading a whole input file, with the errors every reader reports the same way.
#include <string>

namespace tecido::io {

/// The file's bytes. Throws InputError(path, "", ...) for a missing file, a directory, an
/// unreadable file or a read error.
std::string read_text_file(const std::string& path);

}  // namespace tecido::io
