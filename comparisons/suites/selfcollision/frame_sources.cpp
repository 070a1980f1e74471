#include "comparisons/suites/selfcollision/frame_sources.h"

#include "comparisons/io/scene_json.h"
#include "core/geometry/bounded_plane.h"
#include "core/scene/cloth_builder.h"

#include <algorithm>

namespace tecido::suites::selfcollision {

FrameSet seed_fig21_frames(const Settings& s, const std::string& data_dir) {
  Scene scene = io::load_scene(data_dir + "/scenes/seed_fig21_self_contact.json");
  scene.self_collision.reset();
  const long long steps = static_cast<long long>(s.seed_duration / scene.dt);
  const long long every = std::max(1LL, static_cast<long long>(s.seed_frame_interval / scene.dt));
  return record_frames(scene, steps, every, s.frames_per_source, s.contact_share);
}

namespace {
/// The crumpling cloth: 5 cm spacing, 0.3 kg, soft springs, tilted 37 degrees, 0.6 m above a
/// 6 m x 6 m floor with friction 0.9, particles with restitution 0.1.
Scene crumple_scene(int n) {
  Scene scene;
  scene.dt = 0.002;
  scene.forces.gravity = Vec3(0, 0, -9.81);
  scene.forces.air_drag = 0.002;
  ClothGridSpec g;
  g.rows = g.cols = n;
  g.spacing = 0.05;
  g.origin = Vec3(-0.4, -0.4, 0.6);
  g.axis_u = Vec3(1, 0, 0);
  g.axis_v = Vec3(0, 0.8, 0.6);
  g.total_mass = 0.3;
  g.stiffness_b = 20.0;
  g.elasticity = 0.1;
  append_cloth(scene, g);
  for (auto& k : scene.particles.elasticity) k = 0.1;
  scene.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(3, 3), 0.9));
  return scene;
}
}  // namespace

FrameSet crumple_frames(const Settings& s, const std::string&) {
  return record_frames(crumple_scene(s.crumple_grid), s.crumple_steps, s.crumple_every, s.frames_per_source,
                       s.contact_share);
}

const std::vector<FrameSource>& frame_sources() {
  static const std::vector<FrameSource> table = {
      {"seed-fig21", "the seed's experiment scene (fig. 21) without a response", &seed_fig21_frames},
      {"crumple", "a soft cloth crumpling onto a floor", &crumple_frames},
  };
  return table;
}

}  // namespace tecido::suites::selfcollision
