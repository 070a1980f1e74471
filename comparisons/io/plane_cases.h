#pragma once
/// The cases file of `tecido plane` (docs/design.md section 3):
/// {"cases":[{"id":"..","plane":{...},"from":[..],"to":[..],"truth":bool?}, ...]}: an optional
/// boolean "truth" (the suite's disagreement files carry the referee's hit there). Unknown keys
/// (labels; the suite's "engine", "answer", "referee") are ignored.
/// Ids are unique (an absent id is the case's index; comparisons/io/entry_id.h); at most
/// kMaxCases cases.
#include "comparisons/io/json_reader.h"
#include "core/geometry/bounded_plane.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido::io {

struct PlaneCase {
  std::string id;
  BoundedPlane plane;
  Vec3 from, to;
  std::optional<bool> truth;  ///< whether the segment meets the bounded plane, when the file says
};

/// Reads and validates a cases file; throws InputError.
std::vector<PlaneCase> load_plane_cases(const std::string& path);
std::vector<PlaneCase> plane_cases_from_json(const Json& doc, const std::string& file);
/// The inverse, for files the suites write (ids kept; numbers printed to round-trip).
Json plane_cases_to_json(const std::vector<PlaneCase>& cases);

}  // namespace tecido::io
