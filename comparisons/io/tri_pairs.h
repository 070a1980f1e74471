#pragma once
/// The pairs file of `tecido tritri` (docs/design.md section 3):
/// {"pairs":[{"id":"..","a":[[x,y,z],[x,y,z],[x,y,z]],"b":[[..],[..],[..]],"truth":bool?}]}: an
/// optional boolean "truth" (the suite's disagreement files carry the referee's answer there).
/// Unknown keys (labels; the suite's "engine", "answer", "referee") are ignored. Coordinates must be finite (|x| <= 1e15). Ids are unique (an absent id
/// is the pair's index; comparisons/io/entry_id.h); at most kMaxPairs pairs.
#include "comparisons/io/json_reader.h"
#include "core/geometry/types.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido::io {

struct TriPair {
  std::string id;
  Triangle a, b;
  std::optional<bool> truth;  ///< whether the closed triangles intersect, when the file says
};

std::vector<TriPair> load_tri_pairs(const std::string& path);
std::vector<TriPair> tri_pairs_from_json(const Json& doc, const std::string& file);
/// The inverse (17 significant digits: the doubles round-trip exactly; "truth" where set).
Json tri_pairs_to_json(const std::vector<TriPair>& pairs);

}  // namespace tecido::io
