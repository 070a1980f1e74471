#pragma once
/// A Bullet engine of reference/ (bullet_deformable.h's DeformableTwin, bullet_softbody.h's
/// ClassicSoftBody, bullet_obstacle_world.h's BulletObstacleWorld) behind the DynamicsEngine
/// interface. reference/ depends on core only, so its engines cannot implement an interface of
/// comparisons/: they offer the same stepping calls as plain members, and this adapter forwards
/// each one. The arrow stays comparisons -> reference -> core.
#include "comparisons/engines/dynamics_engine.h"

#include <utility>

namespace tecido::engines {

template <class Body>
class BulletDynamics final : public DynamicsEngine {
 public:
  /// Builds the body in place from the body's own constructor arguments (a Bullet world is not
  /// copyable).
  template <class... Args>
  explicit BulletDynamics(Args&&... args) : body_(std::forward<Args>(args)...) {}
  bool step() override { return body_.step(); }
  std::vector<Vec3> positions() const override { return body_.positions(); }
  std::vector<Vec3> velocities() const override { return body_.velocities(); }
  std::vector<std::string> not_modelled() const override { return body_.not_modelled(); }
  double time() const override { return body_.time(); }
  long long steps_done() const override { return body_.steps_done(); }
  const Body& body() const { return body_; }

 private:
  Body body_;
};

}  // namespace tecido::engines
