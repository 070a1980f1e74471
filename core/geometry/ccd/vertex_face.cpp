#include "core/geometry/ccd/vertex_face.h"

#include "core/geometry/ccd/pipeline.h"

namespace tecido {

CcdAnswer ccd_vertex_face(const CcdQuery& q, const CcdSettings& settings) {
  const CcdSettings clamped = ccd_clamped(settings);
  if (q.kind == CcdKind::VertexFace) return ccd_pipeline(q, clamped);
  CcdQuery vf = q;
  vf.kind = CcdKind::VertexFace;
  return ccd_pipeline(vf, clamped);
}

CcdAnswer ccd_vertex_face(const CcdQuery& q) {
  static const CcdSettings defaults = ccd_clamped(CcdSettings{});
  if (q.kind == CcdKind::VertexFace) return ccd_pipeline(q, defaults);
  return ccd_vertex_face(q, defaults);
}

}  // namespace tecido
