#pragma once
/// Reading one bounded plane from JSON, shared by the scene reader and the plane-cases reader.
#include "comparisons/io/json_reader.h"
#include "core/geometry/bounded_plane.h"

namespace tecido::io {

/// {"position","normal","forward","half_extents":[hx,hy],"friction"?}: normal and forward
/// non-zero and not parallel (forward is orthogonalised against the normal, both normalised),
/// half extents >= 0, friction in [0,1]. strict: unknown keys are errors (scenes); otherwise
/// ignored (cases files may carry labels).
BoundedPlane read_bounded_plane(const JsonReader& r, const Json& j, const std::string& where, bool strict);

}  // namespace tecido::io
