#pragma once
/// Continuous collision of a vertex against a triangle, each point moving linearly over the
/// step: core's test, with zero false negatives (the argument is in ccd/ccd.h).
#include "core/geometry/ccd/query.h"
#include "core/geometry/ccd/settings.h"

namespace tecido {

/// Whether the vertex q.x*[0] touches the closed triangle q.x*[1..3] at some t in [0, 1]
/// (q.kind is not read: the points are taken as vertex-face), and a time of impact toi no
/// later than the first contact. Never misses a contact; reports a near miss as a hit only
/// within the distance tolerance of `settings`; NaN or infinite input: hit at toi = 0.
/// Method and guarantees: ccd/ccd.h.
CcdAnswer ccd_vertex_face(const CcdQuery& q, const CcdSettings& settings);
/// The same with the default settings (distance tolerance 1e-9 of the query's scale, time
/// tolerance 2^-20).
CcdAnswer ccd_vertex_face(const CcdQuery& q);

}  // namespace tecido
