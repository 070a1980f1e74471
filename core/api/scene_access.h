#pragma once
/// The public Scene (include/tecido/simulation.h) around core's own: what the public classes hold,
/// and the door tecido::harness uses to wrap a scene read from a file (harness::load_scene).
#include "core/scene/scene.h"

#include <tecido/simulation.h>

namespace tecido::core::detail {

struct SceneData {
  ::tecido::Scene scene;
};

struct SceneAccess {
  static const ::tecido::Scene& scene(const core::Scene& s) { return s.d_->scene; }
  /// A public Scene holding `scene` as it is (no check: a scene file's reader has validated it).
  static core::Scene wrap(::tecido::Scene scene) {
    core::Scene s;
    s.d_->scene = std::move(scene);
    return s;
  }
};

}  // namespace tecido::core::detail
