#include "core/geometry/ccd_projected_quadratics.h"

#include <algorithm>
#include <cmath>

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

/// The axis along which (X0 + X1) x (Y0 + Y1), twice the mid-step normal, is largest.
int projection_axis(const CcdSystem& s) {
  double x[3], y[3];
  for (int c = 0; c < 3; ++c) {
    x[c] = s.d[0][CcdSystem::X][c] + s.d[1][CcdSystem::X][c];
    y[c] = s.d[0][CcdSystem::Y][c] + s.d[1][CcdSystem::Y][c];
  }
  const double n[3] = {std::fabs(x[1] * y[2] - x[2] * y[1]), std::fabs(x[2] * y[0] - x[0] * y[2]),
                       std::fabs(x[0] * y[1] - x[1] * y[0])};
  int axis = 2;
  if (n[0] > n[axis]) axis = 0;
  if (n[1] > n[axis]) axis = 1;
  return axis;
}

}  // namespace

void ccd_projected_quadratics(const CcdSystem& s, double q[3][kCcdMaxQuadratics], CcdProjectedQuadratics& out) {
  const bool vf = s.kind == CcdKind::VertexFace;
  out.axis = projection_axis(s);
  out.count = vf ? 4 : 5;
  const int i = (out.axis + 1) % 3, j = (out.axis + 2) % 3;
  for (int k = 0; k < out.count; ++k) {
    const int* uv = vf ? kVertexFace[k] : kEdgeEdge[k];
    const double* u0 = s.d[0][uv[0]];
    const double* u1 = s.d[1][uv[0]];
    const double* v0 = s.d[0][uv[1]];
    const double* v1 = s.d[1][uv[1]];
    q[0][k] = u0[i] * v0[j] - u0[j] * v0[i];
    q[1][k] = ((u0[i] * v1[j] - u0[j] * v1[i]) + (u1[i] * v0[j] - u1[j] * v0[i])) * 0.5;
    q[2][k] = u1[i] * v1[j] - u1[j] * v1[i];
    const double p0 = std::fabs(u0[i] * v0[j]) + std::fabs(u0[j] * v0[i]);
    const double p1 = (std::fabs(u0[i] * v1[j]) + std::fabs(u0[j] * v1[i]) + std::fabs(u1[i] * v0[j]) +
                       std::fabs(u1[j] * v0[i])) * 0.5;
    const double p2 = std::fabs(u1[i] * v1[j]) + std::fabs(u1[j] * v1[i]);
    CcdErrorBound& e = out.err[k];
    e.e0 = 0x1p-50 * std::max(p0, std::max(p1, p2)) + 0x1p-900;
    e.set_step(std::max(std::fabs(q[0][k]), std::max(std::fabs(q[1][k]), std::fabs(q[2][k]))));
  }
  if (vf) {
    for (int c = 0; c < 3; ++c) q[c][4] = q[c][3];
    out.err[4] = out.err[3];
  }
}

}  // namespace tecido
