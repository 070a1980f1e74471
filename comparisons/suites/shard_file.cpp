#include "comparisons/suites/shard_file.h"

#include "comparisons/io/input_error.h"

#include <fmt/format.h>

#include <limits>

namespace tecido::suites {

void read_shard_position(const io::JsonReader& rd, ShardFile& s) {
  const io::Json& pos = rd.require_array(s.doc["shard"], "/shard");
  if (pos.size() != 2) rd.fail("/shard", "expected [i, n]");
  s.count = static_cast<int>(rd.integer(pos[1], "/shard/1", 1, std::numeric_limits<int>::max()));
  s.index = static_cast<int>(rd.integer(pos[0], "/shard/0", 0, s.count - 1));
}

std::vector<const ShardFile*> shards_by_index(const std::vector<ShardFile>& shards) {
  if (shards.empty()) return {};
  const ShardFile& first = shards.front();
  const int n = first.count;
  std::vector<const ShardFile*> by_index(static_cast<std::size_t>(n), nullptr);
  for (const auto& s : shards) {
    if (s.count != n)
      throw io::InputError(s.file, "/shard",
                           fmt::format("shard {}/{} does not belong with the {}-way shards of {}", s.index, s.count, n,
                                       first.file));
    if (by_index[s.index])
      throw io::InputError(s.file, "/shard",
                           fmt::format("shard {}/{} given twice (also {})", s.index, n, by_index[s.index]->file));
    by_index[s.index] = &s;
  }
  for (int i = 0; i < n; ++i)
    if (!by_index[i])
      throw io::InputError(first.file, "/shard",
                           fmt::format("shard {}/{} is missing ({} of {} shards given)", i, n, shards.size(), n));
  return by_index;
}

}  // namespace tecido::suites
