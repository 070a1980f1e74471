#pragma once
/// Text from outside tecido (a user's file, an engine's reply or stderr) made safe to print: a
/// terminal, a report or a log shows it as text, never acts on it. Printable ASCII and well-formed
/// UTF-8 stay as they are (an engine's message may be in any language); \n, \r and \t become those
/// escapes; every other byte (control bytes, C1 controls, a byte of malformed or overlong UTF-8,
/// surrogates) becomes \xNN.
#include <string>
#include <string_view>

namespace tecido::io {

std::string escaped_text(std::string_view bytes);

}  // namespace tecido::io
