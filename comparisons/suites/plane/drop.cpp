#include "comparisons/suites/plane/drop.h"

#include "comparisons/suites/plane/theory.h"
#include "comparisons/suites/sweep.h"
#include "core/simulation/simulation.h"

#include "reference/bullet_deformable.h"
#include "reference/bullet_rigid_drop.h"

#include <algorithm>
#include <cmath>

namespace tecido::suites::plane {

double drop_duration(const DropSettings& s, double z0) {
  return contact_time(z0, 0.0, s.gravity) + s.into_fall * rebound_flight(z0, s.elasticity, s.gravity);
}

namespace {

Scene core_drop_scene(const DropSettings& s, double z0) {
  Scene scene;
  scene.integrator = IntegratorKind::Midpoint;
  scene.dt = s.dt;
  scene.forces.gravity = Vec3(0, 0, -s.gravity);
  scene.particles.add(Vec3(0, 0, z0), Vec3::Zero(), 1.0, s.elasticity, false);
  scene.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(),
                                            Vec2(s.floor_half_extent, s.floor_half_extent), 0.0));
  return scene;
}

void run_core(const DropSettings& s, const Scene& scene, DropRow& row) {
  Simulation sim(scene);
  sim.set_log_contacts(true);
  const double duration = drop_duration(s, row.z0);
  double apex = -INFINITY;
  while (sim.time() < duration && sim.step())
    if (!sim.contact_log().empty()) apex = std::max(apex, sim.particles().x[0].z());
  row.t_core = sim.contact_log().empty() ? NAN : sim.contact_log().front().time;
  row.apex_core = std::isfinite(apex) ? apex : NAN;
}

void run_bullet(const DropSettings& s, const Scene& scene, DropRow& row) {
  const double duration = drop_duration(s, row.z0);
  const auto rigid = reference::bullet_sphere_drop(row.z0, 0.0, s.gravity, s.elasticity, s.sphere_radius, s.dt, duration);
  row.t_rigid = rigid.contact_time >= 0 ? rigid.contact_time : NAN;
  row.apex_rigid = rigid.contact_time >= 0 ? rigid.rebound_apex : NAN;
  reference::DeformableTwin twin(scene);
  row.node_margin = twin.plane_contact_offset();
  row.node_not_modelled = twin.not_modelled();
  row.t_node = NAN;
  double apex = -INFINITY;
  while (twin.time() < duration && twin.step()) {
    const double z = twin.positions()[0].z();
    if (std::isnan(row.t_node) && z <= row.node_margin + s.node_slack) row.t_node = twin.time();
    if (!std::isnan(row.t_node)) apex = std::max(apex, z);
  }
  row.apex_node = std::isfinite(apex) ? apex : NAN;
  row.bullet = true;
}

}  // namespace

DropRow run_drop(const DropSettings& s, double z0) {
  DropRow row;
  row.z0 = z0;
  row.t_exact = contact_time(z0, 0.0, s.gravity);
  row.apex_exact = rebound_apex(z0, s.elasticity);
  const Scene scene = core_drop_scene(s, z0);
  run_core(s, scene, row);
  run_bullet(s, scene, row);
  return row;
}

io::Json drop_json(const DropRow& r) {
  return {{"z0", num(r.z0)},
          {"t_exact", num(r.t_exact)},
          {"apex_exact", num(r.apex_exact)},
          {"t_core", num(r.t_core)},
          {"apex_core", num(r.apex_core)},
          {"bullet", r.bullet},
          {"t_rigid", num(r.t_rigid)},
          {"apex_rigid", num(r.apex_rigid)},
          {"t_node", num(r.t_node)},
          {"apex_node", num(r.apex_node)},
          {"node_margin", num(r.node_margin)},
          {"node_not_modelled", r.node_not_modelled}};
}

DropRow drop_from_json(const io::Json& j) {
  DropRow r;
  r.z0 = get_num(j.at("z0"));
  r.t_exact = get_num(j.at("t_exact"));
  r.apex_exact = get_num(j.at("apex_exact"));
  r.t_core = get_num(j.at("t_core"));
  r.apex_core = get_num(j.at("apex_core"));
  r.bullet = j.at("bullet").get<bool>();
  r.t_rigid = get_num(j.at("t_rigid"));
  r.apex_rigid = get_num(j.at("apex_rigid"));
  r.t_node = get_num(j.at("t_node"));
  r.apex_node = get_num(j.at("apex_node"));
  r.node_margin = get_num(j.at("node_margin"));
  r.node_not_modelled = j.at("node_not_modelled").get<std::vector<std::string>>();
  return r;
}

}  // namespace tecido::suites::plane
