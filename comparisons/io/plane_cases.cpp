#include "comparisons/io/plane_cases.h"

#include "comparisons/io/entry_id.h"
#include "comparisons/io/limits.h"

#include "comparisons/io/plane_json.h"
#include "comparisons/io/scene_json.h"

namespace tecido::io {

std::vector<PlaneCase> plane_cases_from_json(const Json& doc, const std::string& file) {
  return read_entries<PlaneCase>(doc, file, "cases", kMaxCases, [](const JsonReader& r, const Json& c, const std::string& w) {
    PlaneCase pc;
    pc.plane = read_bounded_plane(r, r.require(c, w, "plane"), child(w, "plane"), /*strict=*/false);
    pc.from = r.vec3(r.require(c, w, "from"), child(w, "from"), kMaxCoordinate);
    pc.to = r.vec3(r.require(c, w, "to"), child(w, "to"), kMaxCoordinate);
    if (c.contains("truth")) pc.truth = r.boolean(c["truth"], child(w, "truth"));
    return pc;
  });
}

std::vector<PlaneCase> load_plane_cases(const std::string& path) { return plane_cases_from_json(read_json_file(path), path); }

Json plane_cases_to_json(const std::vector<PlaneCase>& cases) {
  Json arr = Json::array();
  auto v3 = [](const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); };
  for (const auto& c : cases) {
    arr.push_back({{"id", c.id},
                   {"plane",
                    {{"position", v3(c.plane.position)},
                     {"normal", v3(c.plane.normal)},
                     {"forward", v3(c.plane.forward)},
                     {"half_extents", Json::array({c.plane.half_extents.x(), c.plane.half_extents.y()})}}},
                   {"from", v3(c.from)},
                   {"to", v3(c.to)}});
    if (c.truth) arr.back()["truth"] = *c.truth;
  }
  return Json{{"cases", arr}};
}

}  // namespace tecido::io
