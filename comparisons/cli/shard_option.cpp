#include "comparisons/cli/shard_option.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"

#include <stdexcept>

namespace tecido::cli {

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const std::string bad = "--shard: \"" + text + "\" is not i/n with 0 <= i < n <= " + std::to_string(io::kMaxShards);
  if (slash == std::string::npos) throw io::UsageError(bad);
  const std::string a = text.substr(0, slash), b = text.substr(slash + 1);
  const auto digits = [](const std::string& s) {
    return !s.empty() && s.size() <= 9 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (!digits(a) || !digits(b)) throw io::UsageError(bad);
  const int i = std::stoi(a), n = std::stoi(b);
  if (n < 1 || n > io::kMaxShards || i >= n) throw io::UsageError(bad);
  return {i, n};
}

}  // namespace tecido::cli
