#include "comparisons/cli/error_line.h"

#include "comparisons/io/escaped_text.h"

#include <ostream>

namespace tecido::cli {

std::string one_line(std::string_view message, std::size_t max_length) {
  const std::string out = io::escaped_text(message);
  if (out.size() <= max_length) return out;
  // Cut at character boundaries: a UTF-8 continuation byte (10xxxxxx) never starts a piece.
  const auto continuation = [&](std::size_t k) { return (static_cast<unsigned char>(out[k]) & 0xc0) == 0x80; };
  std::size_t head = max_length / 2, tail = out.size() - max_length / 2;
  while (head > 0 && continuation(head)) --head;
  while (tail < out.size() && continuation(tail)) ++tail;
  return out.substr(0, head) + " ... " + out.substr(tail);
}

void report_error(std::ostream& err, std::string_view message) { err << "tecido: " << one_line(message) << "\n"; }

}  // namespace tecido::cli
