#include "comparisons/cli/shard_option.h"

#include "comparisons/io/input_error.h"

#include <stdexcept>

namespace tecido::cli {

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  try {
    if (slash == std::string::npos) throw std::invalid_argument(text);
    const std::string a = text.substr(0, slash), b = text.substr(slash + 1);
    std::size_t used = 0;
    const int i = std::stoi(a, &used);
    if (used != a.size()) throw std::invalid_argument(text);
    const int n = std::stoi(b, &used);
    if (used != b.size() || n < 1 || i < 0 || i >= n) throw std::invalid_argument(text);
    return {i, n};
  } catch (const std::exception&) {
    throw io::UsageError("--shard: \"" + text + "\" is not i/n with 0 <= i < n");
  }
}

}  // namespace tecido::cli
