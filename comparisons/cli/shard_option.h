#pragma once
/// The `--shard i/n` option shared by the sharded commands (`experiment`, `suite`).
#include <string>
#include <utility>

namespace tecido::cli {

/// "i/n" -> (i, n) with 0 <= i < n <= io::kMaxShards (decimal digits only); throws
/// io::UsageError naming --shard otherwise.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace tecido::cli
