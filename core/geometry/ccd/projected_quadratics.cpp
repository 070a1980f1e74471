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
  // The vectors projected by index first (i = axis + 1, j = axis + 2), then the template with
  // the identity projection (.x, .y): the same values as its lane-by-lane selection, without
  // 40 selects per query at width 1.
  const int i = (out.axis + 1) % 3, j = (out.axis + 2) % 3;
  const Projection<Lanes> flat{false, false};
  for (int k = 0; k < out.count; ++k) {
    const int* uv = vf ? kVertexFace[k] : kEdgeEdge[k];
    const double* u0 = s.d[0][uv[0]];
    const double* u1 = s.d[1][uv[0]];
    const double* v0 = s.d[0][uv[1]];
    const double* v1 = s.d[1][uv[1]];
    double c[3];
    CcdErrorBound& e = out.err[k];
    projected_quadratic<Lanes>(flat, {u0[i], u0[j], 0.0}, {u1[i], u1[j], 0.0}, {v0[i], v0[j], 0.0}, {v1[i], v1[j], 0.0}, c,
                               e.e0, e.step);
    for (int r = 0; r < 3; ++r) q[r][k] = c[r];
  }
  if (vf) {
    for (int c = 0; c < 3; ++c) q[c][4] = q[c][3];
    out.err[4] = out.err[3];
  }
}

}  // namespace tecido
