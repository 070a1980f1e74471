#include "core/geometry/ccd/system.h"

#include <cfloat>
#include <algorithm>
#include <cmath>

namespace tecido {

namespace {

/// The five difference vectors as (minuend, subtrahend) point indices, per kind.
constexpr int kPairs[2][5][2] = {
    {{2, 1}, {3, 1}, {0, 1}, {2, 0}, {3, 0}},  // vertex-face (p, a, b, c): b-a, c-a, p-a, b-p, c-p
    {{1, 0}, {2, 3}, {2, 0}, {1, 2}, {0, 3}},  // edge-edge (a0, a1, b0, b1): a1-a0, b0-b1, b0-a0, a1-b0, a0-b1
};

/// Fills s.d with the differences of the points of kind K (0 vertex-face, 1 edge-edge), each
/// point first multiplied by `scale` (a power of two; none when kScaled is false), s.mag,
/// s.vec_mag and s.scale.
/// Returns the largest |component| and, in sum, a sum of all |components| (NaN or infinite
/// when an input is, or when a difference overflowed; finite otherwise, since 30 components of
/// at most DBL_MAX / 32 cannot overflow it, and larger ones exceed 2^128 anyway). The indices
/// are compile-time constants, so the loops unroll; the maxima and the sum are reduced as
/// trees (max is exact in any order), not as one chain through all 30 components.
template <int K, bool kScaled>
double differences_of(const CcdQuery& q, double scale, CcdSystem& s, double& sum) {
  double a[2][5][3];
  for (int time = 0; time < 2; ++time) {
    const std::array<Vec3, 4>& x = time == 0 ? q.x0 : q.x1;
    for (int k = 0; k < 5; ++k) {
      for (int c = 0; c < 3; ++c) {
        const double p = x[kPairs[K][k][0]][c], r = x[kPairs[K][k][1]][c];
        const double v = kScaled ? p * scale - r * scale : p - r;
        s.d[time][k][c] = v;
        a[time][k][c] = std::fabs(v);
      }
    }
  }
  const auto mx = [](double u, double v) { return u > v ? u : v; };
  double pq = 0.0, acc[3];
  for (int c = 0; c < 3; ++c) {
    // X, Y, Z over both times: s.mag; P, Q apart (they enter m, not the scale).
    s.mag[c] = mx(mx(mx(a[0][0][c], a[1][0][c]), mx(a[0][1][c], a[1][1][c])), mx(a[0][2][c], a[1][2][c]));
    pq = mx(pq, mx(mx(a[0][3][c], a[1][3][c]), mx(a[0][4][c], a[1][4][c])));
    acc[c] = ((a[0][0][c] + a[1][0][c]) + (a[0][1][c] + a[1][1][c])) +
             ((a[0][2][c] + a[1][2][c]) + ((a[0][3][c] + a[1][3][c]) + (a[0][4][c] + a[1][4][c])));
  }
  for (int k = 0; k < 3; ++k)
    s.vec_mag[k] = mx(mx(mx(a[0][k][0], a[1][k][0]), mx(a[0][k][1], a[1][k][1])), mx(a[0][k][2], a[1][k][2]));
  sum = (acc[0] + acc[1]) + acc[2];
  s.scale = mx(mx(s.mag[0], s.mag[1]), s.mag[2]);
  return mx(s.scale, pq);
}

double differences(const CcdQuery& q, double scale, CcdSystem& s, double& sum) {
  if (q.kind == CcdKind::VertexFace) return differences_of<0, true>(q, scale, s, sum);
  return differences_of<1, true>(q, scale, s, sum);
}

double differences(const CcdQuery& q, CcdSystem& s, double& sum) {
  if (q.kind == CcdKind::VertexFace) return differences_of<0, false>(q, 1.0, s, sum);
  return differences_of<1, false>(q, 1.0, s, sum);
}

bool inputs_finite(const CcdQuery& q) {
  for (const auto* x : {&q.x0, &q.x1})
    for (const Vec3& p : *x)
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(p[c])) return false;
  return true;
}

}  // namespace

CcdPrepared prepare_ccd_system(const CcdQuery& q, CcdSystem& s) {
  s.kind = q.kind;
  double sum = 0.0;
  double m = differences(q, s, sum);
  if (!(sum <= DBL_MAX) || m > 0x1p128) {
    // Rare: huge coordinates, an overflowed difference, or a non-finite input. Scale the
    // points down by a power of two so that the largest is below 1 in magnitude: then no
    // difference can overflow (points tinier than 2^-1074 after scaling lose their value, an
    // absolute error below 2^-1074 per difference, covered by the bounds' pads).
    if (!inputs_finite(q)) return CcdPrepared::NonFinite;
    double big = 0.0;
    for (const auto* x : {&q.x0, &q.x1})
      for (const Vec3& p : *x) big = std::fmax(big, p.cwiseAbs().maxCoeff());
    int e = 0;
    std::frexp(big, &e);
    m = differences(q, std::ldexp(1.0, -e), s, sum);
  }
  if (m == 0.0) return CcdPrepared::AllCoincide;
  if (m < 0x1p-128) {
    // Tiny query: scale the differences up (exact: a power of two, no overflow possible), and
    // with them their maxima.
    int e = 0;
    std::frexp(m, &e);
    const double up = std::ldexp(1.0, -e);
    for (auto& per_time : s.d)
      for (auto& v : per_time)
        for (double& c : v) c *= up;
    for (double& c : s.mag) c *= up;
    for (double& c : s.vec_mag) c *= up;
    s.scale *= up;
  }
  return CcdPrepared::Ok;
}

}  // namespace tecido
