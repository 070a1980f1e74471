#include "core/geometry/ccd/edge_edge.h"

#include "core/geometry/ccd/pipeline.h"

namespace tecido {

CcdAnswer ccd_edge_edge(const CcdQuery& q, const CcdSettings& settings) {
  const CcdSettings clamped = ccd_clamped(settings);
  if (q.kind == CcdKind::EdgeEdge) return ccd_pipeline(q, clamped);
  CcdQuery ee = q;
  ee.kind = CcdKind::EdgeEdge;
  return ccd_pipeline(ee, clamped);
}

CcdAnswer ccd_edge_edge(const CcdQuery& q) {
  static const CcdSettings defaults = ccd_clamped(CcdSettings{});
  if (q.kind == CcdKind::EdgeEdge) return ccd_pipeline(q, defaults);
  return ccd_edge_edge(q, defaults);
}

}  // namespace tecido
