#include "comparisons/io/scene_json.h"

#include "comparisons/io/obstacle_json.h"
#include "comparisons/io/plane_json.h"
#include "core/scene/cloth_builder.h"

#include <cmath>
#include <memory>
#include <random>

namespace tecido::io {

namespace {

/// "random": {"seed": integer >= 0 (default: the scene's seed), "heading_diffusion": D [rad^2/s] in
/// [0, 1e3], "knot_interval": tau [s] in [1e-3, 1e3] (default 0.1)} inside "wind": the seed's random
/// wind (core/dynamics/random_wind.h). Its knots are prepared by the caller.
RandomHeading read_random_heading(const JsonReader& r, const Json& j, const std::string& w, std::uint64_t seed) {
  r.require_object(j, w);
  r.only_keys(j, w, {"seed", "heading_diffusion", "knot_interval"});
  RandomHeading h;
  h.seed = j.contains("seed") ? static_cast<std::uint64_t>(r.integer(j["seed"], child(w, "seed"), 0, INT64_MAX)) : seed;
  h.diffusion = r.number_in(r.require(j, w, "heading_diffusion"), child(w, "heading_diffusion"), 0.0, 1e3);
  if (j.contains("knot_interval")) {
    h.knot_interval = r.number_in(j["knot_interval"], child(w, "knot_interval"), 1e-3, 1e3);
  }
  return h;
}

Wind read_wind(const JsonReader& r, const Json& j, const std::string& w, std::uint64_t seed) {
  Wind wind;
  if (j.is_array()) {
    wind.force = r.vec3(j, w, 1e9);
    return wind;
  }
  r.require_object(j, w);
  r.only_keys(j, w, {"force", "swirl", "random"});
  wind.force = r.vec3(r.require(j, w, "force"), child(w, "force"), 1e9);
  if (j.contains("swirl")) {
    const std::string ws = child(w, "swirl");
    const Json& s = r.require_object(j["swirl"], ws);
    r.only_keys(s, ws, {"rate", "axis", "phase"});
    wind.swirl = true;
    wind.rate = r.number(r.require(s, ws, "rate"), child(ws, "rate"), 1e6);
    if (s.contains("axis")) {
      wind.axis = r.vec3(s["axis"], child(ws, "axis"));
      if (!(wind.axis.norm() > 1e-12)) r.fail(child(ws, "axis"), "axis must not be zero");
      wind.axis.normalize();
    }
    if (s.contains("phase")) {
      wind.phase = r.number(s["phase"], child(ws, "phase"), 1e6);
    } else {
      std::mt19937_64 rng(seed);
      wind.phase = static_cast<double>(rng() >> 11) * 0x1.0p-53 * 2.0 * M_PI;
    }
  }
  if (j.contains("random")) {
    if (!wind.swirl) r.fail(child(w, "random"), "needs \"swirl\" (the axis the heading turns about, its mean rate)");
    wind.random = std::make_shared<const RandomHeading>(read_random_heading(r, j["random"], child(w, "random"), seed));
  }
  return wind;
}

/// `needs_k`: as for listed particles, a cloth that a plane or an obstacle without elasticity can
/// hit needs its own k (no hidden default: the restitution decides every bounce).
ClothGridSpec read_cloth(const JsonReader& r, const Json& j, const std::string& w, bool needs_k) {
  r.require_object(j, w);
  r.only_keys(j, w, {"rows", "cols", "spacing", "origin", "axis_u", "axis_v", "total_mass", "stiffness_b",
                     "stiffness_a", "damping", "elasticity", "pins"});
  ClothGridSpec c;
  c.rows = static_cast<int>(r.integer(r.require(j, w, "rows"), child(w, "rows"), 2, kMaxClothSide));
  c.cols = static_cast<int>(r.integer(r.require(j, w, "cols"), child(w, "cols"), 2, kMaxClothSide));
  // Fewer than 8 springs and 2 triangles per node: 2^20 nodes take a few hundred MB.
  if (static_cast<long long>(c.rows) * c.cols > kMaxClothNodes)
    r.fail(child(w, "cols"), "rows x cols = " + std::to_string(static_cast<long long>(c.rows) * c.cols) +
                                 " nodes, more than the limit of " + std::to_string(kMaxClothNodes));
  c.spacing = r.number(r.require(j, w, "spacing"), child(w, "spacing"), 1e6);
  if (!(c.spacing > 0.0)) r.fail(child(w, "spacing"), "spacing must be > 0");
  c.origin = r.vec3(r.require(j, w, "origin"), child(w, "origin"), kMaxCoordinate);
  c.axis_u = r.vec3(r.require(j, w, "axis_u"), child(w, "axis_u"));
  c.axis_v = r.vec3(r.require(j, w, "axis_v"), child(w, "axis_v"));
  if (!(c.axis_u.norm() > 1e-12)) r.fail(child(w, "axis_u"), "axis must not be zero");
  if (!(c.axis_v.norm() > 1e-12)) r.fail(child(w, "axis_v"), "axis must not be zero");
  c.axis_u.normalize();
  c.axis_v.normalize();
  if (std::abs(c.axis_u.dot(c.axis_v)) > 1e-9) r.fail(child(w, "axis_v"), "axis_v must be orthogonal to axis_u");
  c.total_mass = r.number(r.require(j, w, "total_mass"), child(w, "total_mass"), kMaxMass);
  if (!(c.total_mass > 0.0)) r.fail(child(w, "total_mass"), "total mass must be > 0");
  if (c.total_mass / (static_cast<double>(c.rows) * c.cols) < kMinMass)
    r.fail(child(w, "total_mass"), "total mass too small: each node's mass must be at least 1e-300 kg (its inverse must be finite)");
  c.stiffness_b = r.number_in(r.require(j, w, "stiffness_b"), child(w, "stiffness_b"), 0.0, 1e12);
  if (j.contains("stiffness_a")) c.stiffness_a = r.number_in(j["stiffness_a"], child(w, "stiffness_a"), 0.0, 1e12);
  if (j.contains("damping")) c.damping = r.number_in(j["damping"], child(w, "damping"), 0.0, 1e12);
  if (j.contains("elasticity")) {
    c.elasticity = r.number_in(j["elasticity"], child(w, "elasticity"), 0.0, 1.0);
  } else if (needs_k) {
    r.fail(child(w, "elasticity"), "missing required key (the scene has planes or obstacles)");
  }
  if (j.contains("pins")) {
    const std::string wp = child(w, "pins");
    const Json& pins = r.require_array(j["pins"], wp);
    for (std::size_t k = 0; k < pins.size(); ++k) {
      const std::string wk = child(wp, k);
      if (!pins[k].is_array() || pins[k].size() != 2) r.fail(wk, "expected [row, col]");
      const int pr = static_cast<int>(r.integer(pins[k][0], child(wk, 0), 0, c.rows - 1));
      const int pc = static_cast<int>(r.integer(pins[k][1], child(wk, 1), 0, c.cols - 1));
      c.pins.push_back({pr, pc});
    }
  }
  return c;
}

/// "self_collision": {"detection": "discrete" (default) | "continuous",
///                    "response": "none"|"gia"|"edge1"|"edge2"|"edge3"|"gia+edge3"|"impulse",
///                    "strength": force per pushed particle [N] (>= 0; required by gia and the edge modes),
///                    "every": detect after every k-th step (integer >= 1, default 1)}
/// "impulse" needs "detection": "continuous". Needs a cloth (the triangle mesh it tests).
/// See core/cloth/self_collision_settings.h.
SelfCollisionSettings read_self_collision(const JsonReader& r, const Json& j, const std::string& w) {
  r.require_object(j, w);
  r.only_keys(j, w, {"detection", "response", "strength", "every"});
  SelfCollisionSettings sc;
  if (j.contains("detection")) {
    const std::string d = r.string(j["detection"], child(w, "detection"));
    const auto det = parse_self_collision_detection(d);
    if (!det) r.fail(child(w, "detection"), "unknown detection \"" + d + "\" (discrete, continuous)");
    sc.detection = *det;
  }
  const std::string name = r.string(r.require(j, w, "response"), child(w, "response"));
  const auto resp = parse_self_collision_response(name);
  if (!resp)
    r.fail(child(w, "response"), "unknown response \"" + name + "\" (none, gia, edge1, edge2, edge3, gia+edge3, impulse)");
  sc.response = *resp;
  if (sc.response == SelfCollisionResponse::Impulse && sc.detection != SelfCollisionDetection::Continuous)
    r.fail(child(w, "response"), "\"impulse\" needs \"detection\": \"continuous\" (a time of impact)");
  const bool forced = sc.response != SelfCollisionResponse::None && sc.response != SelfCollisionResponse::Impulse;
  if (j.contains("strength")) {
    sc.strength = r.number_in(j["strength"], child(w, "strength"), 0.0, 1e9);
  } else if (forced) {
    r.fail(child(w, "strength"), "missing required key (the response needs a force)");
  }
  if (j.contains("every")) sc.every = static_cast<int>(r.integer(j["every"], child(w, "every"), 1, 1000000000));
  return sc;
}

/// The lengths of the scene's lists, checked before any entry is read (the cloth's share is
/// added where it is built).
void check_list_sizes(const JsonReader& r, const Json& doc) {
  if (doc.contains("particles"))
    r.at_most(r.require_array(doc["particles"], "/particles").size(), "/particles", kMaxParticles, "particles");
  if (doc.contains("springs"))
    r.at_most(r.require_array(doc["springs"], "/springs").size(), "/springs", kMaxSprings, "springs");
  if (doc.contains("planes")) r.at_most(r.require_array(doc["planes"], "/planes").size(), "/planes", kMaxPlanes, "planes");
  if (doc.contains("obstacles"))
    r.at_most(r.require_array(doc["obstacles"], "/obstacles").size(), "/obstacles", kMaxObstacles, "obstacles");
}

void read_contact(const JsonReader& r, const Json& c, ContactSettings& contact) {
  r.require_object(c, "/contact");
  r.only_keys(c, "/contact", {"static_threshold", "tangential_threshold", "bisection_tolerance", "max_events_per_step"});
  if (c.contains("static_threshold"))
    contact.static_threshold = r.number_in(c["static_threshold"], "/contact/static_threshold", 0.0, 1e6);
  if (c.contains("tangential_threshold"))
    contact.tangential_threshold = r.number_in(c["tangential_threshold"], "/contact/tangential_threshold", 0.0, 1e6);
  if (c.contains("bisection_tolerance")) {
    contact.bisection_tolerance = r.number(c["bisection_tolerance"], "/contact/bisection_tolerance", kMaxDt);
    if (!(contact.bisection_tolerance > 0.0)) r.fail("/contact/bisection_tolerance", "must be > 0");
  }
  if (c.contains("max_events_per_step"))
    contact.max_events_per_step =
        static_cast<int>(r.integer(c["max_events_per_step"], "/contact/max_events_per_step", 1, 1000000));
}

/// `needs_k`: every free particle needs its own k (a plane, or an obstacle without elasticity, can hit it).
void read_particles(const JsonReader& r, const Json& ps, bool needs_k, Particles& particles) {
  r.require_array(ps, "/particles");
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const std::string w = child("/particles", k);
    const Json& p = r.require_object(ps[k], w);
    r.only_keys(p, w, {"position", "velocity", "mass", "pinned", "elasticity"});
    const Vec3 x = r.vec3(r.require(p, w, "position"), child(w, "position"), kMaxCoordinate);
    Vec3 v = Vec3::Zero();
    if (p.contains("velocity")) v = r.vec3(p["velocity"], child(w, "velocity"), kMaxSpeed);
    const bool pinned = p.contains("pinned") && r.boolean(p["pinned"], child(w, "pinned"));
    double mass = 0.0;
    if (!pinned || p.contains("mass")) {
      mass = r.number(r.require(p, w, "mass"), child(w, "mass"), kMaxMass);
      if (!(mass > 0.0)) r.fail(child(w, "mass"), "mass must be > 0 (a free particle needs a positive mass)");
      if (mass < kMinMass) r.fail(child(w, "mass"), "mass must be at least 1e-300 kg (its inverse must be finite)");
    }
    double k_el = 1.0;
    if (p.contains("elasticity")) {
      k_el = r.number_in(p["elasticity"], child(w, "elasticity"), 0.0, 1.0);
    } else if (needs_k && !pinned) {
      r.fail(child(w, "elasticity"), "missing required key (the scene has planes or obstacles)");
    }
    particles.add(x, v, mass, k_el, pinned);
  }
}

/// Appends the cloth once its nodes fit beside the listed particles.
void add_cloth(const JsonReader& r, const Json& j, bool needs_k, Scene& s) {
  const ClothGridSpec cloth = read_cloth(r, j, "/cloth", needs_k);
  const std::size_t nodes = static_cast<std::size_t>(cloth.rows) * static_cast<std::size_t>(cloth.cols);
  r.at_most(s.particles.size() + nodes, "/cloth", kMaxParticles,
            "particles (" + std::to_string(s.particles.size()) + " listed and " + std::to_string(nodes) + " of the cloth)");
  append_cloth(s, cloth);
}

/// Appends the listed springs once they fit beside the cloth's.
void read_springs(const JsonReader& r, const Json& ss, Scene& s) {
  r.require_array(ss, "/springs");
  if (!s.forces.springs.empty())
    r.at_most(ss.size() + s.forces.springs.size(), "/springs", kMaxSprings,
              "springs (" + std::to_string(ss.size()) + " listed and " + std::to_string(s.forces.springs.size()) +
                  " of the cloth)");
  const auto n = static_cast<std::int64_t>(s.particles.size());
  for (std::size_t k = 0; k < ss.size(); ++k) {
    const std::string w = child("/springs", k);
    const Json& sp = r.require_object(ss[k], w);
    r.only_keys(sp, w, {"i", "j", "stiffness", "rest_length", "damping"});
    Spring spring;
    spring.i = static_cast<int>(r.integer(r.require(sp, w, "i"), child(w, "i"), 0, n - 1));
    spring.j = static_cast<int>(r.integer(r.require(sp, w, "j"), child(w, "j"), 0, n - 1));
    if (spring.i == spring.j) r.fail(child(w, "j"), "a spring needs two different particles");
    spring.stiffness = r.number_in(r.require(sp, w, "stiffness"), child(w, "stiffness"), 0.0, 1e12);
    spring.rest_length = sp.contains("rest_length")
                             ? r.number_in(sp["rest_length"], child(w, "rest_length"), 0.0, kMaxCoordinate)
                             : (s.particles.x[spring.j] - s.particles.x[spring.i]).norm();
    if (sp.contains("damping")) spring.damping = r.number_in(sp["damping"], child(w, "damping"), 0.0, 1e12);
    s.forces.springs.push_back(spring);
  }
}

}  // namespace

Scene scene_from_json(const Json& doc, const std::string& file) {
  JsonReader r(file);
  const std::string root;
  r.require_object(doc, root);
  r.only_keys(doc, root, {"integrator", "dt", "steps", "seed", "gravity", "air_drag", "wind", "particles", "springs",
                          "planes", "contact", "cloth", "self_collision", "obstacles", "edge_contacts"});
  check_list_sizes(r, doc);
  Scene s;
  if (doc.contains("integrator")) {
    const std::string name = r.string(doc["integrator"], "/integrator");
    auto k = parse_integrator(name);
    if (!k) r.fail("/integrator", "unknown integrator \"" + name + "\" (euler, symplectic, midpoint, rk4)");
    s.integrator = *k;
  }
  s.dt = r.number(r.require(doc, root, "dt"), "/dt", kMaxDt);
  if (!(s.dt > 0.0)) r.fail("/dt", "dt must be > 0");
  s.steps = r.integer(r.require(doc, root, "steps"), "/steps", 0, kMaxSteps);
  if (doc.contains("seed")) s.seed = static_cast<std::uint64_t>(r.integer(doc["seed"], "/seed", 0, INT64_MAX));
  if (doc.contains("gravity")) s.forces.gravity = r.vec3(doc["gravity"], "/gravity", 1e6);
  if (doc.contains("air_drag")) s.forces.air_drag = r.number_in(doc["air_drag"], "/air_drag", 0.0, 1e12);
  if (doc.contains("wind")) s.forces.wind = read_wind(r, doc["wind"], "/wind", s.seed);
  if (s.forces.wind && s.forces.wind->random) {
    auto h = std::make_shared<RandomHeading>(*s.forces.wind->random);
    h->prepare(static_cast<double>(s.steps) * s.dt);
    s.forces.wind->random = std::move(h);
  }

  const bool has_planes = doc.contains("planes");
  // Every free particle (listed or of the cloth) needs its own k when a plane, or an obstacle without elasticity, can hit it.
  const bool needs_k = has_planes || (doc.contains("obstacles") && obstacles_use_particle_k(doc["obstacles"]));
  if (has_planes) {
    const Json& planes = r.require_array(doc["planes"], "/planes");
    for (std::size_t k = 0; k < planes.size(); ++k) s.planes.push_back(read_bounded_plane(r, planes[k], child("/planes", k), /*strict=*/true));
  }
  if (doc.contains("contact")) read_contact(r, doc["contact"], s.contact);
  if (doc.contains("particles")) read_particles(r, doc["particles"], needs_k, s.particles);
  if (doc.contains("cloth")) add_cloth(r, doc["cloth"], needs_k, s);
  if (doc.contains("self_collision")) {
    s.self_collision = read_self_collision(r, doc["self_collision"], "/self_collision");
    if (s.triangles.empty()) r.fail("/self_collision", "self-collision needs a cloth (the triangle mesh it tests)");
  }
  if (s.particles.size() == 0) r.fail("/particles", "the scene has no particles (give particles or a cloth)");
  if (doc.contains("obstacles")) {
    s.obstacles = read_obstacles(r, doc["obstacles"], "/obstacles", file);
    check_particles_outside(r, s.obstacles, "/obstacles", s.particles.x, s.particles.pinned);
  }
  if (doc.contains("edge_contacts")) s.edge_contacts = r.boolean(doc["edge_contacts"], "/edge_contacts");
  if (doc.contains("springs")) read_springs(r, doc["springs"], s);
  return s;
}

Scene load_scene(const std::string& path) { return scene_from_json(read_json_file(path), path); }

}  // namespace tecido::io
