#include "comparisons/suites/plane/contact_time.h"

#include "comparisons/suites/plane/theory.h"
#include "comparisons/suites/random.h"
#include "comparisons/suites/sweep.h"
#include "comparisons/suites/thread_cpu_time.h"
#include "core/simulation/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::plane {

DropStart drop_start(const ContactTimeSettings& s, std::uint64_t seed, int d) {
  Rng r(substream(seed, s.first_stream + static_cast<std::uint64_t>(d)));
  DropStart out;
  out.z0 = r.uniform(s.height_lo, s.height_hi);
  const double vz = r.uniform(s.vz_lo, s.vz_hi);
  const double vy = r.uniform(-s.v_horizontal, s.v_horizontal);  // drawn y first, as the velocity always was
  out.v = Vec3(r.uniform(-s.v_horizontal, s.v_horizontal), vy, vz);
  return out;
}

Scene drop_scene(const ContactTimeSettings& s, const DropStart& start, IntegratorKind k, double h, double tolerance) {
  Scene scene;
  scene.integrator = k;
  scene.dt = h;
  scene.contact.bisection_tolerance = tolerance;
  scene.forces.gravity = Vec3(0, 0, -s.gravity);
  scene.particles.add(Vec3(0, 0, start.z0), start.v, s.mass, s.elasticity, false);
  scene.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(),
                                            Vec2(s.floor_half_extent, s.floor_half_extent), 0.0));
  return scene;
}

ContactCellResult run_contact_cell(const ContactTimeSettings& s, std::uint64_t seed, IntegratorKind k, double h, int level) {
  ContactCellResult out;
  out.tolerance = std::ldexp(h, -level);
  long long bisections = 0;
  for (int d = 0; d < s.drops; ++d) {
    const DropStart start = drop_start(s, seed, d);
    Simulation sim(drop_scene(s, start, k, h, out.tolerance));
    sim.set_log_contacts(true);
    const double t0 = thread_cpu_seconds();
    while (sim.contact_log().empty() && sim.time() < s.max_time && sim.step()) {
    }
    out.seconds += thread_cpu_seconds() - t0;
    if (sim.contact_log().empty()) {
      if (out.first_missing < 0) out.first_missing = d;
      continue;
    }
    ++out.contacts;
    const double err = std::abs(sim.contact_log().front().time - contact_time(start.z0, start.v.z(), s.gravity));
    out.max_error = std::max(out.max_error, err);
    bisections += sim.contacts().bisections;
  }
  out.bisections = out.contacts > 0 ? static_cast<double>(bisections) / out.contacts : std::nan("");
  return out;
}

ContactTable empty_contact_table(const ContactTimeSettings& s) {
  const std::size_t n = s.levels.size();
  ContactTable t;
  t.cells.assign(s.integrators.size(),
                 std::vector<std::vector<ContactCellResult>>(s.steps.size(), std::vector<ContactCellResult>(n)));
  t.error.assign(s.integrators.size(), std::vector<std::vector<std::string>>(s.steps.size(), std::vector<std::string>(n)));
  return t;
}

std::string missing_reason(const ContactTimeSettings& s, const ContactCellResult& r, const std::string& error) {
  if (!error.empty()) return error;
  if (r.first_missing >= 0)
    return fmt::format("drop {} made no contact within {:g} s ({} of {} did)", r.first_missing, s.max_time, r.contacts,
                       s.drops);
  return "";
}

io::Json cell_json(const ContactCellResult& r) {
  return {{"tolerance", num(r.tolerance)}, {"max_error", num(r.max_error)},   {"contacts", r.contacts},
          {"first_missing", r.first_missing}, {"bisections", num(r.bisections)}, {"seconds", num(r.seconds)}};
}

ContactCellResult cell_from_json(const io::Json& j) {
  ContactCellResult r;
  r.tolerance = get_num(j.at("tolerance"));
  r.max_error = get_num(j.at("max_error"));
  r.contacts = j.at("contacts").get<int>();
  r.first_missing = j.at("first_missing").get<int>();
  r.bisections = get_num(j.at("bisections"));
  r.seconds = get_num(j.at("seconds"));
  return r;
}

}  // namespace tecido::suites::plane
