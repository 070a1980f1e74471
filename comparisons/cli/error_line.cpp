#include "comparisons/cli/error_line.h"

#include <cstdio>
#include <ostream>

namespace tecido::cli {

std::string one_line(std::string_view message, std::size_t max_length) {
  std::string out;
  out.reserve(message.size());
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    } else {
      out += c;
    }
  }
  if (out.size() <= max_length) return out;
  const std::size_t half = max_length / 2;
  return out.substr(0, half) + " ... " + out.substr(out.size() - half);
}

void report_error(std::ostream& err, std::string_view message) { err << "tecido: " << one_line(message) << "\n"; }

}  // namespace tecido::cli
