#include "comparisons/io/escaped_text.h"

#include <cstdint>
#include <cstdio>

namespace tecido::io {

namespace {

/// Length of the well-formed UTF-8 sequence of 2-4 bytes starting at s[i] (RFC 3629: no overlong
/// forms, no surrogates, nothing past U+10FFFF), excluding the C1 controls U+0080..U+009F; 0 when none.
std::size_t utf8_sequence(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const unsigned char lead = b(0);
  const std::size_t n = lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : lead >= 0xc2 ? 2 : 0;
  if (n == 0 || lead > 0xf4 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((b(k) & 0xc0) != 0x80) return 0;
  if (n == 2 && lead == 0xc2 && b(1) < 0xa0) return 0;  // C1 controls
  if (n == 3 && lead == 0xe0 && b(1) < 0xa0) return 0;  // overlong
  if (n == 3 && lead == 0xed && b(1) >= 0xa0) return 0;  // surrogates
  if (n == 4 && lead == 0xf0 && b(1) < 0x90) return 0;  // overlong
  if (n == 4 && lead == 0xf4 && b(1) >= 0x90) return 0;  // past U+10FFFF
  return n;
}

void append_hex(std::string& out, unsigned char u) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "\\x%02x", u);
  out += hex;
}

}  // namespace

std::string escaped_text(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  for (std::size_t i = 0; i < bytes.size();) {
    const auto u = static_cast<unsigned char>(bytes[i]);
    if (u >= 0x20 && u < 0x7f) {
      out += bytes[i++];
    } else if (u == '\n' || u == '\r' || u == '\t') {
      out += u == '\n' ? "\\n" : u == '\r' ? "\\r" : "\\t";
      ++i;
    } else if (const std::size_t n = u >= 0x80 ? utf8_sequence(bytes, i) : 0; n > 0) {
      out.append(bytes.substr(i, n));
      i += n;
    } else {
      append_hex(out, u);
      ++i;
    }
  }
  return out;
}

}  // namespace tecido::io
