// The only translation unit that includes libccd.
#include "reference/ccd_adapter.h"

#include <ccd/ccd.h>

#include <cmath>
#include <limits>

namespace tecido::reference {
namespace {

/// Shared by both objects of one query: watches what libccd asks of the support functions.
struct Monitor {
  unsigned long calls = 0;
  unsigned long cap = 0;
  bool bad_direction = false;  ///< a NaN/Inf search direction was seen
  bool capped = false;         ///< the call budget ran out
};

struct CcdTriangle {
  ccd_vec3_t v[3];
  ccd_vec3_t centroid;
  Monitor* monitor;
};

CcdTriangle make(const Triangle& t, Monitor* m) {
  CcdTriangle o{};
  for (int i = 0; i < 3; ++i) ccdVec3Set(&o.v[i], t[i].x(), t[i].y(), t[i].z());
  const Vec3 c = (t[0] + t[1] + t[2]) / 3.0;
  ccdVec3Set(&o.centroid, c.x(), c.y(), c.z());
  o.monitor = m;
  return o;
}

/// Support: the corner maximising dir . v (first one on ties). Once the monitor's budget is
/// spent it answers NaN, which makes every loop of libccd's GJK and MPR stop (their
/// continuation tests are comparisons that NaN fails) and the adapter reports "no answer".
void support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* t = static_cast<const CcdTriangle*>(obj);
  Monitor& m = *t->monitor;
  ++m.calls;
  const double dx = ccdVec3X(dir), dy = ccdVec3Y(dir), dz = ccdVec3Z(dir);
  if (!std::isfinite(dx) || !std::isfinite(dy) || !std::isfinite(dz)) m.bad_direction = true;
  if (m.calls > m.cap) {
    m.capped = true;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    ccdVec3Set(out, nan, nan, nan);
    return;
  }
  int best = 0;
  double best_dot = ccdVec3Dot(&t->v[0], dir);
  for (int i = 1; i < 3; ++i) {
    const double d = ccdVec3Dot(&t->v[i], dir);
    if (d > best_dot) {
      best_dot = d;
      best = i;
    }
  }
  ccdVec3Copy(out, &t->v[best]);
}

void center(const void* obj, ccd_vec3_t* out) {
  ccdVec3Copy(out, &static_cast<const CcdTriangle*>(obj)->centroid);
}

bool finite(const Triangle& t) {
  for (const Vec3& v : t)
    if (!v.allFinite()) return false;
  return true;
}

enum class Algo { Gjk, Mpr };

std::optional<bool> run(const Triangle& a, const Triangle& b, Algo algo) {
  if (!finite(a) || !finite(b)) return std::nullopt;
  Monitor m;
  // Each support call of libccd calls support1 and support2 once: GJK makes 1 + iterations
  // Minkowski support calls, so the cap below is never the binding one for GJK.
  m.cap = algo == Algo::Gjk ? 2 * (kCcdMaxIterations + 2) : 2 * 4 * kCcdMaxIterations;
  const CcdTriangle ta = make(a, &m), tb = make(b, &m);
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = support;
  ccd.support2 = support;
  ccd.center1 = center;
  ccd.center2 = center;
  ccd.max_iterations = kCcdMaxIterations;
  // Defaults kept and stated: mpr_tolerance 1e-4 (used by MPR's portal refinement),
  // epa_tolerance 1e-4 and dist_tolerance 1e-6 (unused by the boolean queries).
  const int hit = algo == Algo::Gjk ? ccdGJKIntersect(&ta, &tb, &ccd) : ccdMPRIntersect(&ta, &tb, &ccd);
  if (m.bad_direction || m.capped) return std::nullopt;
  // GJK gives up silently after max_iterations: 1 + max_iterations Minkowski supports.
  if (algo == Algo::Gjk && !hit && m.calls >= 2 * (kCcdMaxIterations + 1)) return std::nullopt;
  return hit != 0;
}

}  // namespace

std::optional<bool> ccd_gjk_tri_tri(const Triangle& a, const Triangle& b) { return run(a, b, Algo::Gjk); }

std::optional<bool> ccd_mpr_tri_tri(const Triangle& a, const Triangle& b) { return run(a, b, Algo::Mpr); }

}  // namespace tecido::reference
