#include "core/geometry/ccd/ccd.h"

namespace tecido {

CcdAnswer ccd(const CcdQuery& q, const CcdSettings& settings) {
  return q.kind == CcdKind::VertexFace ? ccd_vertex_face(q, settings) : ccd_edge_edge(q, settings);
}

CcdAnswer ccd(const CcdQuery& q) { return q.kind == CcdKind::VertexFace ? ccd_vertex_face(q) : ccd_edge_edge(q); }

}  // namespace tecido
