#include "comparisons/io/tri_pairs.h"

#include "comparisons/io/entry_id.h"
#include "comparisons/io/limits.h"

namespace tecido::io {

namespace {
Triangle read_triangle(const JsonReader& r, const Json& j, const std::string& w) {
  if (!j.is_array() || j.size() != 3) r.fail(w, "expected an array of 3 points");
  Triangle t;
  for (std::size_t k = 0; k < 3; ++k) t[k] = r.vec3(j[k], child(w, k), 1e15);
  return t;
}
}  // namespace

std::vector<TriPair> tri_pairs_from_json(const Json& doc, const std::string& file) {
  return read_entries<TriPair>(doc, file, "pairs", kMaxPairs, [](const JsonReader& r, const Json& p, const std::string& w) {
    TriPair tp;
    tp.a = read_triangle(r, r.require(p, w, "a"), child(w, "a"));
    tp.b = read_triangle(r, r.require(p, w, "b"), child(w, "b"));
    if (p.contains("truth")) tp.truth = r.boolean(p["truth"], child(w, "truth"));
    return tp;
  });
}

std::vector<TriPair> load_tri_pairs(const std::string& path) { return tri_pairs_from_json(read_json_file(path), path); }

Json tri_pairs_to_json(const std::vector<TriPair>& pairs) {
  Json arr = Json::array();
  auto tri = [](const Triangle& t) {
    Json j = Json::array();
    for (const Vec3& v : t) j.push_back({v.x(), v.y(), v.z()});
    return j;
  };
  for (const auto& p : pairs) {
    Json j = {{"id", p.id}, {"a", tri(p.a)}, {"b", tri(p.b)}};
    if (p.truth) j["truth"] = *p.truth;
    arr.push_back(std::move(j));
  }
  return Json{{"pairs", arr}};
}

}  // namespace tecido::io
