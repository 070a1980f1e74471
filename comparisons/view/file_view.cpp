#include "comparisons/view/file_view.h"

#include "comparisons/io/ccd_queries.h"
#include "comparisons/io/plane_cases.h"
#include "comparisons/io/tri_pairs.h"

#include <filesystem>
#include <stdexcept>

namespace tecido::view {

namespace {

bool answer_shaped(const io::Json& a, const char* time_key) {
  if (!a.is_object() || !a.contains("hit") || !a["hit"].is_boolean()) return false;
  if (!time_key || !a.contains(time_key)) return true;
  return a[time_key].is_number() || a[time_key].is_null();
}

/// Copies the labels of entry `from` that have their types onto `to`.
void copy_labels(const io::Json& from, io::Json& to, const char* time_key) {
  if (!from.is_object()) return;
  if (from.contains("engine") && from["engine"].is_string()) to["engine"] = from["engine"];
  for (const char* key : {"answer", "referee"}) {
    if (!from.contains(key) || !answer_shaped(from[key], time_key)) continue;
    io::Json a{{"hit", from[key]["hit"]}};
    if (time_key && from[key].contains(time_key)) a[time_key] = from[key][time_key];
    to[key] = a;
  }
}

}  // namespace

io::Json file_view_data(const std::string& kind, const std::string& path) {
  const io::Json raw = io::read_json_file(path);
  io::Json doc;
  const char* list = nullptr;
  const char* time_key = nullptr;
  if (kind == "tritri") {
    doc = io::tri_pairs_to_json(io::tri_pairs_from_json(raw, path)), list = "pairs";
  } else if (kind == "plane") {
    doc = io::plane_cases_to_json(io::plane_cases_from_json(raw, path)), list = "cases", time_key = "t";
  } else if (kind == "ccd") {
    doc = io::ccd_queries_to_json(io::ccd_queries_from_json(raw, path)), list = "queries", time_key = "toi";
  } else {
    throw std::logic_error("file_view_data: unknown kind " + kind);
  }
  io::Json& out = doc[list];
  for (std::size_t k = 0; k < out.size(); ++k) copy_labels(raw[list][k], out[k], time_key);
  return {{"kind", kind}, {"file", std::filesystem::path(path).filename().string()}, {"doc", doc}};
}

}  // namespace tecido::view
