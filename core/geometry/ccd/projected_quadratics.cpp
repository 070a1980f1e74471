#include "core/geometry/ccd/projected_quadratics.h"

#include "core/geometry/ccd/decisions.h"

namespace tecido {

namespace {

/// (U, V) vector pairs of the quadratics, den first.
constexpr int kVertexFace[4][2] = {
    {CcdSystem::X, CcdSystem::Y}, {CcdSystem::Z, CcdSystem::Y}, {CcdSystem::X, CcdSystem::Z}, {CcdSystem::P, CcdSystem::Q}};
constexpr int kEdgeEdge[5][2] = {{CcdSystem::X, CcdSystem::Y},
                                 {CcdSystem::Z, CcdSystem::Y},
                                 {CcdSystem::X, CcdSystem::Z},
                                 {CcdSystem::P, CcdSystem::Y},
                                 {CcdSystem::X, CcdSystem::Q}};

}  // namespace

void ccd_projected_quadratics(const CcdSystem& s, double q[3][kCcdMaxQuadratics], CcdProjectedQuadratics& out) {
  using namespace ccd_scalar;
  const bool vf = s.kind == CcdKind::VertexFace;
  const Projection<Lanes> pr = projection<Lanes>(v3(s.d[0][CcdSystem::X]), v3(s.d[1][CcdSystem::X]),
                                                 v3(s.d[0][CcdSystem::Y]), v3(s.d[1][CcdSystem::Y]));
  out.axis = pr.axis1 ? 1 : (pr.axis0 ? 0 : 2);
  out.count = vf ? 4 : 5;
  for (int k = 0; k < out.count; ++k) {
    const int* uv = vf ? kVertexFace[k] : kEdgeEdge[k];
    double c[3];
    CcdErrorBound& e = out.err[k];
    projected_quadratic<Lanes>(pr, v3(s.d[0][uv[0]]), v3(s.d[1][uv[0]]), v3(s.d[0][uv[1]]), v3(s.d[1][uv[1]]), c, e.e0,
                               e.step);
    for (int j = 0; j < 3; ++j) q[j][k] = c[j];
  }
  if (vf) {
    for (int c = 0; c < 3; ++c) q[c][4] = q[c][3];
    out.err[4] = out.err[3];
  }
}

}  // namespace tecido
