#include "comparisons/io/plane_json.h"

#include "comparisons/io/scene_json.h"

namespace tecido::io {

BoundedPlane read_bounded_plane(const JsonReader& r, const Json& j, const std::string& w, bool strict) {
  r.require_object(j, w);
  if (strict) r.only_keys(j, w, {"position", "normal", "forward", "half_extents", "friction"});
  const Vec3 pos = r.vec3(r.require(j, w, "position"), child(w, "position"), kMaxCoordinate);
  const Vec3 n = r.vec3(r.require(j, w, "normal"), child(w, "normal"));
  const Vec3 f = r.vec3(r.require(j, w, "forward"), child(w, "forward"));
  if (!(n.norm() > 1e-12)) r.fail(child(w, "normal"), "normal must not be zero");
  if (!(f.norm() > 1e-12)) r.fail(child(w, "forward"), "forward must not be zero");
  if (n.normalized().cross(f.normalized()).norm() < 1e-9) r.fail(child(w, "forward"), "forward is parallel to the normal");
  const Vec2 he = r.vec2(r.require(j, w, "half_extents"), child(w, "half_extents"), kMaxCoordinate);
  if (he.x() < 0.0) r.fail(child(child(w, "half_extents"), 0), "half extent must be >= 0");
  if (he.y() < 0.0) r.fail(child(child(w, "half_extents"), 1), "half extent must be >= 0");
  double friction = 0.0;
  if (j.contains("friction")) friction = r.number_in(j["friction"], child(w, "friction"), 0.0, 1.0);
  return make_bounded_plane(pos, n, f, he, friction);
}

}  // namespace tecido::io
