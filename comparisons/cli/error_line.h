#pragma once
/// The one line on stderr of every failed command (docs/design.md section 3): "tecido: " and the
/// message, which may quote hostile text (a key, an id, a file name): control characters are
/// escaped and an overlong message keeps its start and its end, so it stays one readable line.
#include <iosfwd>
#include <string>
#include <string_view>

namespace tecido::cli {

/// `message` on one line (io::escaped_text: \n, \r, \t as escapes, control bytes and malformed
/// UTF-8 as \xNN); when longer than `max_length`, its first and last halves around " ... ".
std::string one_line(std::string_view message, std::size_t max_length = 2000);

/// Writes "tecido: <one_line(message)>\n" to `err`.
void report_error(std::ostream& err, std::string_view message);

}  // namespace tecido::cli
