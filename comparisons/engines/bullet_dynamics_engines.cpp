#include "comparisons/engines/bullet_dynamics_engines.h"

#include "comparisons/engines/bullet_dynamics.h"
#include "comparisons/engines/classic_klst.h"
#include "reference/bullet_deformable.h"
#include "reference/bullet_softbody.h"

#include <string>
#include <utility>

namespace tecido::engines {

namespace {

DynamicsEntry bullet_entry(std::string name, double evaluations) {
  DynamicsEntry e;
  e.name = std::move(name);
  e.source = DynamicsSource::Bullet;
  e.integrator = IntegratorKind::Symplectic;  // the method the engines' scenes are set to
  e.evaluations_per_step = evaluations;
  return e;
}

DynamicsEntry deformable_entry() {
  DynamicsEntry e = bullet_entry("bullet-deformable", 1.0);  // one spring-force evaluation per symplectic step
  e.make = [](const Scene& scene) -> std::unique_ptr<DynamicsEngine> {
    Scene sc = scene;
    sc.integrator = IntegratorKind::Symplectic;  // the twin's method
    return std::make_unique<BulletDynamics<reference::DeformableTwin>>(sc);
  };
  return e;
}

DynamicsEntry deformable_implicit_entry(int cg_iterations) {
  // Newton x CG products of the force Jacobian: varies, not counted
  DynamicsEntry e = bullet_entry("bullet-deformable-implicit-it" + std::to_string(cg_iterations), 0.0);
  e.make = [cg_iterations](const Scene& scene) -> std::unique_ptr<DynamicsEngine> {
    reference::DeformableTwinOptions o;
    o.implicit = true;
    o.krylov_iterations = cg_iterations;
    Scene sc = scene;
    sc.integrator = IntegratorKind::Symplectic;
    return std::make_unique<BulletDynamics<reference::DeformableTwin>>(sc, o);
  };
  return e;
}

DynamicsEntry classic_entry(int piterations, const ClassicCalibration& c) {
  DynamicsEntry e = bullet_entry("bullet-classic-it" + std::to_string(piterations), 0.0);  // position-based: no force evaluations
  e.make = [piterations, c](const Scene& scene) -> std::unique_ptr<DynamicsEngine> {
    reference::ClassicSoftBodyOptions o;
    o.klst = classic_klst(scene, scene.dt, piterations, c);  // throws when no calibrated body exists
    o.piterations = piterations;
    o.kdp = 0.0;  // the scene is undamped
    Scene sc = scene;
    sc.integrator = IntegratorKind::Symplectic;
    return std::make_unique<BulletDynamics<reference::ClassicSoftBody>>(sc, o);
  };
  return e;
}

}  // namespace

std::vector<DynamicsEntry> bullet_dynamics_entries(const ClassicCalibration& classic_rules) {
  std::vector<DynamicsEntry> entries;
  entries.push_back(deformable_entry());
  for (int k : {1, 4, 16}) entries.push_back(deformable_implicit_entry(k));
  for (int k : {1, 4, 16}) entries.push_back(classic_entry(k, classic_rules));
  return entries;
}

}  // namespace tecido::engines
