#pragma once
/// Continuous collision of two edges, each end point moving linearly over the step: core's
/// test, with zero false negatives (the argument is in ccd/ccd.h).
#include "core/geometry/ccd/query.h"
#include "core/geometry/ccd/settings.h"

namespace tecido {

/// Whether the closed segments q.x*[0]-q.x*[1] and q.x*[2]-q.x*[3] touch at some t in [0, 1]
/// (q.kind is not read: the points are taken as edge-edge), and a time of impact toi no later
/// than the first contact. Never misses a contact (parallel, collinear and zero-length edges
/// included); reports a near miss as a hit only within the distance tolerance of `settings`;
/// NaN or infinite input: hit at toi = 0. Method and guarantees: ccd/ccd.h.
CcdAnswer ccd_edge_edge(const CcdQuery& q, const CcdSettings& settings);
/// The same with the default settings.
CcdAnswer ccd_edge_edge(const CcdQuery& q);

}  // namespace tecido
