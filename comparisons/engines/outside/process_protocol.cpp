#include "comparisons/engines/outside/process_protocol.h"

#include "comparisons/engines/outside/scene_features.h"
#include "comparisons/io/scene_to_json.h"

#include <cmath>
#include <limits>

namespace tecido::outside {

namespace {

using io::Json;

Json point(const Vec3& p) { return Json::array({p.x(), p.y(), p.z()}); }

template <std::size_t N>
Json points(const std::array<Vec3, N>& ps) {
  Json a = Json::array();
  for (const Vec3& p : ps) a.push_back(point(p));
  return a;
}

std::string excerpt(const Json& j) {
  std::string s = j.dump();
  return s.size() > 120 ? s.substr(0, 120) + "..." : s;
}

const Json& member(const Json& reply, const char* key) {
  if (!reply.is_object()) throw ProtocolError("expected a JSON object, got " + excerpt(reply));
  const auto it = reply.find(key);
  if (it == reply.end()) throw ProtocolError(std::string("reply lacks \"") + key + "\": " + excerpt(reply));
  return *it;
}

/// true/false, or nullopt for null.
std::optional<bool> hit_of(const Json& reply) {
  const Json& h = member(reply, "hit");
  if (h.is_null()) return std::nullopt;
  if (!h.is_boolean()) throw ProtocolError("\"hit\" must be true, false or null, got " + excerpt(h));
  return h.get<bool>();
}

double number_of(const Json& reply, const char* key) {
  const Json& t = member(reply, key);
  if (!t.is_number()) throw ProtocolError(std::string("\"") + key + "\" must be a number, got " + excerpt(t));
  return t.get<double>();
}

/// n points [[x,y,z],...]; null coordinates are NaN.
std::vector<Vec3> state_points(const Json& a, const char* key, std::size_t n) {
  if (!a.is_array() || a.size() != n)
    throw ProtocolError(std::string("\"") + key + "\" must be an array of " + std::to_string(n) + " points");
  std::vector<Vec3> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Json& p = a[i];
    if (!p.is_array() || p.size() != 3)
      throw ProtocolError(std::string("\"") + key + "\"[" + std::to_string(i) + "] must be [x,y,z], got " + excerpt(p));
    for (int c = 0; c < 3; ++c) {
      if (p[c].is_null()) out[i][c] = std::numeric_limits<double>::quiet_NaN();
      else if (p[c].is_number()) out[i][c] = p[c].get<double>();
      else throw ProtocolError(std::string("\"") + key + "\"[" + std::to_string(i) + "] holds " + excerpt(p[c]));
    }
  }
  return out;
}

}  // namespace

const std::string* reply_error(const Json& reply) {
  if (!reply.is_object()) return nullptr;
  const auto it = reply.find("error");
  return it != reply.end() && it->is_string() ? &it->get_ref<const std::string&>() : nullptr;
}

Json hello_request() { return {{"op", "hello"}, {"protocol", kProtocolVersion}}; }

Hello parse_hello(const Json& reply) {
  Hello h;
  // An engine written before the field says nothing and speaks protocol 1.
  const auto v = reply.find("protocol");
  if (v != reply.end() && !(v->is_number_integer() && v->get<long long>() == kProtocolVersion))
    throw ProtocolError("the engine speaks protocol " + excerpt(*v) + ", tecido speaks protocol " +
                        std::to_string(kProtocolVersion) + " (\"protocol\" of the hello reply)");
  const Json& s = member(reply, "supports");
  if (!s.is_array()) throw ProtocolError("\"supports\" must be an array of names, got " + excerpt(s));
  for (const Json& x : s) {
    if (!x.is_string()) throw ProtocolError("\"supports\" must be an array of names, got " + excerpt(x));
    h.supports.insert(x.get<std::string>());
  }
  const auto o = reply.find("order");
  if (o != reply.end() && !o->is_null()) {
    if (!o->is_number() || !(o->get<double>() > 0.0 && o->get<double>() <= 100.0))
      throw ProtocolError("\"order\" must be a number in (0, 100] or null, got " + excerpt(*o));
    h.order = o->get<double>();
  }
  return h;
}

Json tri_tri_query(const TriTriQuery& q) { return {{"a", points(q.a)}, {"b", points(q.b)}}; }

Json ccd_query(const CcdQuery& q) { return {{"kind", ccd_kind_name(q.kind)}, {"t0", points(q.x0)}, {"t1", points(q.x1)}}; }

Json plane_query(const SegmentPlaneQuery& q) {
  const BoundedPlane& p = q.plane;
  return {{"plane",
           {{"position", point(p.position)},
            {"normal", point(p.normal)},
            {"forward", point(p.forward)},
            {"half_extents", Json::array({p.half_extents.x(), p.half_extents.y()})}}},
          {"from", point(q.from)},
          {"to", point(q.to)}};
}

Json with_op(Json query, const std::string& op) {
  query["op"] = op;
  return query;
}

std::optional<bool> parse_tri_tri(const Json& reply) { return hit_of(reply); }

std::optional<CcdAnswer> parse_ccd(const Json& reply) {
  const std::optional<bool> hit = hit_of(reply);
  if (!hit) return std::nullopt;
  if (!*hit) return CcdAnswer{false, 0.0};
  return CcdAnswer{true, number_of(reply, "toi")};
}

std::optional<SegmentPlaneHit> parse_plane(const Json& reply) {
  const std::optional<bool> hit = hit_of(reply);
  if (!hit) return std::nullopt;
  if (!*hit) return SegmentPlaneHit{false, 0.0};
  return SegmentPlaneHit{true, number_of(reply, "t")};
}

std::vector<Json> parse_batch(const Json& reply, std::size_t n) {
  const Json& r = member(reply, "results");
  if (!r.is_array() || r.size() != n)
    throw ProtocolError("\"results\" must be an array of " + std::to_string(n) + " replies, got " +
                        (r.is_array() ? std::to_string(r.size()) : excerpt(r)));
  std::vector<Json> out(r.begin(), r.end());
  for (const Json& x : out)
    if (!x.is_object()) throw ProtocolError("each of \"results\" must be an object, got " + excerpt(x));
  return out;
}

Json create_request(const Scene& scene) {
  return {{"op", "create"}, {"scene", io::scene_to_json(scene)}, {"features", feature_names(feature_bits(scene))}};
}

std::optional<std::string> parse_create(const Json& reply) {
  if (const std::string* e = reply_error(reply)) return *e;
  const Json& ok = member(reply, "ok");
  if (ok != Json(true)) throw ProtocolError("expected {\"ok\":true} or {\"error\":\"...\"}, got " + excerpt(reply));
  return std::nullopt;
}

Json step_request(double dt, long long steps) { return {{"op", "step"}, {"dt", dt}, {"steps", steps}}; }

State parse_step(const Json& reply, std::size_t n) {
  State s;
  s.x = state_points(member(reply, "x"), "x", n);
  s.v = state_points(member(reply, "v"), "v", n);
  return s;
}

}  // namespace tecido::outside
