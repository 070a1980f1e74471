#include "comparisons/view/html_text.h"

#include "comparisons/io/escaped_text.h"

namespace tecido::view {

std::string html_text(std::string_view text) {
  const std::string safe = io::escaped_text(text);
  std::string out;
  out.reserve(safe.size());
  for (char c : safe) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace tecido::view
