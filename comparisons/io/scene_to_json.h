#pragma once
/// A core Scene written in tecido's scene format (scene_json.h), for outside engines: the process
/// door sends it in {"op":"create","scene":...}. A cloth is written expanded, as the particles and
/// springs it was built into (no "cloth" key), so an engine needs no cloth builder; planes, wind
/// and contact settings are written in their own keys. Self-collision is not written (it needs the
/// cloth's mesh): the request's "features" names it, and every other feature beyond particles,
/// springs, gravity and drag (outside/scene_features.h). Numbers round-trip exactly; a scene
/// without self-collision reads back (scene_from_json) as the same particles, springs and forces.
#include "comparisons/io/json_reader.h"
#include "core/scene/scene.h"

namespace tecido::io {

Json scene_to_json(const Scene& scene);

}  // namespace tecido::io
