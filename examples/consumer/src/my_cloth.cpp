// The user's cloth: particles and springs (tecido_scene's arrays), gravity and linear drag,
// stepped by symplectic Euler (v += h a(x, v); x += h v): a first-order method.
#include "my_engine.h"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

struct Cloth {
  std::vector<Eigen::Vector3d> x, v;
  std::vector<double> inverse_mass;
  struct Spring {
    std::uint32_t i, j;
    double k, rest;
  };
  std::vector<Spring> springs;
  Eigen::Vector3d gravity;
  double drag = 0.0;

  std::vector<Eigen::Vector3d> accelerations() const {
    std::vector<Eigen::Vector3d> force(x.size(), Eigen::Vector3d::Zero());
    for (const Spring& s : springs) {
      const Eigen::Vector3d d = x[s.j] - x[s.i];
      const double len = d.norm();
      if (len == 0.0) continue;
      const Eigen::Vector3d f = s.k * (len - s.rest) / len * d;
      force[s.i] += f;
      force[s.j] -= f;
    }
    std::vector<Eigen::Vector3d> a(x.size(), Eigen::Vector3d::Zero());
    for (std::size_t p = 0; p < x.size(); ++p)
      if (inverse_mass[p] > 0.0) a[p] = gravity + inverse_mass[p] * (force[p] - drag * v[p]);
    return a;
  }
};

Eigen::Vector3d vec(const double* p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

}  // namespace

void* my_cloth_create(const tecido_scene* scene, char* why, size_t why_size) {
  if (scene->features != 0) {
    std::snprintf(why, why_size, "models particles, springs, gravity and drag only (features 0x%llx)",
                  static_cast<unsigned long long>(scene->features));
    return nullptr;
  }
  auto* c = new Cloth;
  for (std::size_t p = 0; p < scene->particle_count; ++p) {
    c->x.push_back(vec(scene->positions + 3 * p));
    c->v.push_back(vec(scene->velocities + 3 * p));
    c->inverse_mass.push_back(scene->inverse_masses[p]);
  }
  for (std::size_t s = 0; s < scene->spring_count; ++s)
    c->springs.push_back({scene->spring_ends[2 * s], scene->spring_ends[2 * s + 1], scene->spring_stiffness[s],
                          scene->spring_rest_length[s]});
  c->gravity = vec(scene->gravity);
  c->drag = scene->linear_drag;
  return c;
}

int my_cloth_step(void* simulation, double dt, int64_t steps) {
  Cloth& c = *static_cast<Cloth*>(simulation);
  for (int64_t n = 0; n < steps; ++n) {
    const std::vector<Eigen::Vector3d> a = c.accelerations();
    for (std::size_t p = 0; p < c.x.size(); ++p) {
      c.v[p] += dt * a[p];
      c.x[p] += dt * c.v[p];
    }
  }
  for (std::size_t p = 0; p < c.x.size(); ++p)
    if (!c.x[p].allFinite() || !c.v[p].allFinite()) return 1;
  return 0;
}

void my_cloth_read(const void* simulation, double* positions, double* velocities) {
  const Cloth& c = *static_cast<const Cloth*>(simulation);
  for (std::size_t p = 0; p < c.x.size(); ++p)
    for (int k = 0; k < 3; ++k) positions[3 * p + k] = c.x[p][k], velocities[3 * p + k] = c.v[p][k];
}

void my_cloth_destroy(void* simulation) { delete static_cast<Cloth*>(simulation); }

tecido_engine my_cloth_engine(const char* name, double claimed_order) {
  tecido_engine e{};
  e.name = name;
  e.claimed_order = claimed_order;
  e.create = &my_cloth_create;
  e.step = &my_cloth_step;
  e.read = &my_cloth_read;
  e.destroy = &my_cloth_destroy;
  return e;
}
