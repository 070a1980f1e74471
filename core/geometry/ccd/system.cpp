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
/// point first multiplied by `scale` (a power of two). Returns the largest |component| and, in
/// sum, the sum of all |components| (NaN or infinite when an input is, or when a difference
/// overflowed). The indices are compile-time constants, so the loops unroll.
template <int K>
double differences_of(const CcdQuery& q, double scale, CcdSystem& s, double& sum) {
  double m = 0.0, acc[2] = {0.0, 0.0};
  for (int time = 0; time < 2; ++time) {
    const std::array<Vec3, 4>& x = time == 0 ? q.x0 : q.x1;
    for (int k = 0; k < 5; ++k) {
      for (int c = 0; c < 3; ++c) {
        const double v = x[kPairs[K][k][0]][c] * scale - x[kPairs[K][k][1]][c] * scale;
        s.d[time][k][c] = v;
        const double a = std::fabs(v);
        m = a > m ? a : m;
        acc[time] += a;
      }
    }
  }
  sum = acc[0] + acc[1];
  return m;
}

double differences(const CcdQuery& q, double scale, CcdSystem& s, double& sum) {
  return q.kind == CcdKind::VertexFace ? differences_of<0>(q, scale, s, sum) : differences_of<1>(q, scale, s, sum);
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
  double m = differences(q, 1.0, s, sum);
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
    // Tiny query: scale the differences up (exact: a power of two, no overflow possible).
    int e = 0;
    std::frexp(m, &e);
    const double up = std::ldexp(1.0, -e);
    for (auto& per_time : s.d)
      for (auto& v : per_time)
        for (double& c : v) c *= up;
  }
  s.scale = 0.0;
  for (int c = 0; c < 3; ++c) {
    double mc = 0.0;
    for (int time = 0; time < 2; ++time)
      for (int k = 0; k < 3; ++k) mc = std::max(mc, std::fabs(s.d[time][k][c]));
    s.mag[c] = mc;
    s.scale = std::max(s.scale, mc);
  }
  return CcdPrepared::Ok;
}

}  // namespace tecido
