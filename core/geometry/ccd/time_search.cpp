#include "core/geometry/ccd/time_search.h"

#include "core/geometry/ccd/bernstein.h"
#include "core/geometry/ccd/coplanarity_cubic.h"
#include "core/geometry/ccd/cubic_root.h"
#include "core/geometry/ccd/decisions.h"
#include "core/geometry/ccd/inclusion.h"
#include "core/geometry/ccd/projected_quadratics.h"

#include <algorithm>
#include <cmath>

namespace tecido {

namespace {

/// Intervals visited per query before the rest goes to the inclusion search as whole
/// intervals (a guard: a cubic and five quadratics have at most 13 roots, so an ordinary query
/// needs a few dozen).
constexpr int kMaxNodes = 1024;
/// Intervals this narrow go to the inclusion search when still undecided.
constexpr double kMinWidth = 0x1p-50;

class TimeSearch {
 public:
  TimeSearch(const CcdSystem& s, const CcdSettings& st, CcdStats& stats) : s_(s), settings_(st), stats_(stats) {
    delta_ = st.distance_tolerance * s.scale;
    // Barycentric slack whose effect on the contact point is at most delta / 2: the point
    // moves by at most 5 beta max(|X|, |Y|) <= 5 sqrt(3) beta L (vertex-face; edge-edge
    // 2 sqrt(3) beta L), and 16 sqrt(3) < 27.72.
    beta_ = st.distance_tolerance / 27.72;
  }

  CcdAnswer run() {
    CcdBernsteinSet p;
    ccd_coplanarity_cubic(s_, p.f, ef_);
    if (ccd_certified_sign(p.f, 4, 1, ef_.e0) != 0) {
      stats_.cubic_rejections++;
      return {};
    }
    ccd_projected_quadratics(s_, p.q, pq_);
    all_inside_ = ((1u << pq_.count) - 1) & ~1u;
    visit(0.0, 1.0, 0, p, Known{}, true);
    stats_.time_search_nodes += static_cast<unsigned long long>(nodes_);
    return answer_;
  }

 private:
  /// What an interval inherits from its ancestors: a sign certified on an interval holds on
  /// every part of it (whatever the rounding of the parts' own coefficients).
  struct Known {
    int sd = 0;             ///< the certain sign of den, 0 while unknown
    double den_low = 0.0;   ///< a lower bound of sd * den on the interval, when sd != 0
    unsigned inside = 0;    ///< bit k: numerator k certainly has the sign sd (the point is inside)
  };
  enum Outcome { kMiss = 0, kHit = 1, kNotApplicable = 2, kNoBracket = 3 };

  /// True when a hit was found in [lo, hi] (answer_ set); false when [lo, hi] holds no contact.
  bool visit(double lo, double hi, int depth, const CcdBernsteinSet& p, const Known& inherited, bool jump_ok) {
    // Taken by reference and copied here: passed by value, the struct went through the stack
    // in pieces and was read back whole, a store-forwarding stall on every call.
    Known kn = inherited;
    ++nodes_;
    const double ef = ef_.at(depth);
    if (ccd_certified_sign(p.f, 4, 1, ef) != 0) return false;  // rule 1
    double eq[kCcdMaxQuadratics];
    for (int k = 0; k < kCcdMaxQuadratics; ++k) eq[k] = pq_.err[k].at(depth);
    if (kn.sd == 0) {
      kn.sd = ccd_certified_sign(&p.q[0][0], 3, kCcdMaxQuadratics, eq[0]);
      if (kn.sd != 0) kn.den_low = std::min(std::min(kn.sd * p.q[0][0], kn.sd * p.q[1][0]), kn.sd * p.q[2][0]) - eq[0];
    }
    if (kn.sd != 0) {
      for (int k = 1; k < pq_.count; ++k) {
        if (kn.inside & (1u << k)) continue;
        const int sk = ccd_certified_sign(&p.q[0][k], 3, kCcdMaxQuadratics, eq[k]);
        if (sk == -kn.sd) return false;  // rule 2
        if (sk == kn.sd) kn.inside |= 1u << k;
      }
      // The point is inside wherever the points are coplanar: only the cubic matters now.
      if (kn.inside == all_inside_) return refine(lo, hi, depth, p.f, kn.den_low, jump_ok);
    }
    if (jump_ok) {
      const Outcome o = jump(lo, hi, depth, p.f, p.q, kn);
      if (o == kMiss || o == kHit) return o == kHit;
      jump_ok = o == kNotApplicable;  // a failed bracket would fail again below
    }
    const bool leaf = hi - lo <= settings_.time_tolerance;
    if (kn.sd != 0 && ((leaf && crossing_inside(p, kn, ef, eq)) || near_ends(lo, hi, depth, p.f, p.q, kn, ef, eq)))
      return true;
    const bool den_vanishes = kn.sd == 0 && std::fabs(p.q[0][0]) <= 2.0 * eq[0] &&
                              std::fabs(p.q[1][0]) <= 2.0 * eq[0] && std::fabs(p.q[2][0]) <= 2.0 * eq[0];
    if (hi - lo <= kMinWidth || den_vanishes || nodes_ >= kMaxNodes) return inclusion(lo, hi);
    CcdBernsteinSet left, right;
    ccd_halve(p, left, right);
    const double mid = 0.5 * (lo + hi);
    if (visit(lo, mid, depth + 1, left, kn, jump_ok)) return true;
    return visit(mid, hi, depth + 1, right, kn, jump_ok);
  }

  /// The time search once den's sign and every numerator's are certain on [lo, hi] (the
  /// contact point is inside at every coplanar instant): the earliest root of the cubic alone.
  /// den_low bounds sd * den from below on [lo, hi].
  bool refine(double lo, double hi, int depth, const double f[4], double den_low, bool jump_ok) {
    const double ef = ef_.at(depth);
    if (ccd_certified_sign(f, 4, 1, ef) != 0) return false;  // rule 1
    if (jump_ok) {
      const Outcome o = jump(lo, hi, depth, f, nullptr, Known{});
      if (o == kMiss || o == kHit) return o == kHit;
      jump_ok = o == kNotApplicable;
    }
    if (hi - lo <= settings_.time_tolerance && ((f[0] > ef && f[3] < -ef) || (f[0] < -ef && f[3] > ef)))
      return hit(lo);  // rule 3a
    Known kn;
    kn.den_low = den_low;
    if (near_ends(lo, hi, depth, f, nullptr, kn, ef, nullptr)) return true;  // rule 3b
    if (hi - lo <= kMinWidth || nodes_ >= kMaxNodes) return inclusion(lo, hi);
    ++nodes_;
    const double m01 = (f[0] + f[1]) * 0.5, m12 = (f[1] + f[2]) * 0.5, m23 = (f[2] + f[3]) * 0.5;
    const double n0 = (m01 + m12) * 0.5, n1 = (m12 + m23) * 0.5;
    const double c = (n0 + n1) * 0.5;
    const double left[4] = {f[0], m01, n0, c}, right[4] = {c, n1, m23, f[3]};
    const double mid = 0.5 * (lo + hi);
    if (refine(lo, mid, depth + 1, left, den_low, jump_ok)) return true;
    return refine(mid, hi, depth + 1, right, den_low, jump_ok);
  }

  /// Rule J: when the cubic certainly changes sign on [lo, hi] and is certainly monotone there
  /// (its coefficients' differences, the derivative's Bernstein coefficients up to 3, all of
  /// one sign beyond their error 2 E), it has exactly one root t* in [lo, hi]. Find it
  /// approximately (ccd/cubic_root.h), bracket it by [a, b], b - a = 3h (h a power of two from
  /// 2^-46 up to time_tolerance / 4), and certify the bracket: the cubic restricted to [a, b]
  /// starts and ends with certainly opposite signs. Then the whole of [lo, hi] is decided by
  /// [a, b] alone: with q == nullptr (the point is known to be inside) a hit at a; otherwise
  /// the quadratics restricted to [a, b] decide as rules 2 and 3a do (tight, since [a, b] is
  /// tiny), or the inclusion search does on [a, b]. kNotApplicable when the cubic is not
  /// certainly monotone with a sign change; kNoBracket when no bracket could be certified.
  Outcome jump(double lo, double hi, int depth, const double f[4], const double (*q)[kCcdMaxQuadratics], const Known& kn) {
    using namespace ccd_scalar;
    const double ef = ef_.at(depth);
    double s0 = 0.0;
    if (!monotone_crossing<Lanes>(f, ef, s0)) return kNotApplicable;
    const double w = hi - lo, e1 = ef_.at(depth + 1);
    // The bracket below needs the root to a quarter of its smallest step, 2^-46.
    const double tr = lo + ccd_cubic_root(f, std::max(0x1p-48 / w, 0x1p-52)) * w;  // out of line: decisions.inl at width 1
    double a = 0.0, b = 0.0, sa = 0.0, sb = 0.0;
    if (!certify_bracket<Lanes>(f, tr, lo, hi, w, e1, s0, 0.25 * settings_.time_tolerance, 1u, a, b, sa, sb))
      return kNoBracket;
    if (q == nullptr) return hit(a) ? kHit : kMiss;
    double qk[kCcdMaxQuadratics][3], eq[kCcdMaxQuadratics];
    for (int k = 0; k < kCcdMaxQuadratics; ++k) {
      for (int j = 0; j < 3; ++j) qk[k][j] = q[j][k];
      eq[k] = pq_.err[k].at(depth + 1);
    }
    DenKnown<Lanes> dk;
    dk.dpos = kn.sd > 0;
    dk.dneg = kn.sd < 0;
    dk.sd = kn.sd;
    dk.den_low = kn.den_low;
    for (int k = 0; k < kCcdMaxQuadratics; ++k) dk.inside[k] = (kn.inside & (1u << k)) != 0;
    bool miss = false, in = false, open = false;
    bracket_decision<Lanes>(qk, eq, pq_.count, dk, sa, sb, beta_, miss, in, open);
    if (miss) return kMiss;                          // rule 2 at the only coplanar instant
    if (in) return hit(a) ? kHit : kMiss;            // rule 3a at the only coplanar instant
    return inclusion(a, b) ? kHit : kMiss;           // den of no certain sign, or neither
  }

  bool hit(double lo) {
    answer_ = {true, lo};
    stats_.time_search_hits++;
    return true;
  }

  /// Rules 3a and 3b of ccd/time_search.h on a leaf where den has the certain sign kn.sd.
  /// Rule 3a on a leaf where den has the certain sign kn.sd: a certain sign change of f, and
  /// every numerator above -beta |den| all over the leaf.
  bool crossing_inside(const CcdBernsteinSet& p, const Known& kn, double ef, const double eq[]) const {
    if (!((p.f[0] > ef && p.f[3] < -ef) || (p.f[0] < -ef && p.f[3] > ef))) return false;
    for (int k = 1; k < pq_.count; ++k) {
      if (kn.inside & (1u << k)) continue;
      for (int j = 0; j < 3; ++j)
        if (!(kn.sd * p.q[j][k] >= eq[k] - beta_ * kn.den_low)) return false;
    }
    return true;
  }

  /// Rule 3b at the interval's end j (0: lo, 2: hi; q == nullptr when every numerator is known
  /// inside): |f| / |den| <= delta / 2 and every numerator >= -beta |den| there, so the
  /// primitives are within delta of each other at that instant.
  bool near_at(const double f[4], const double (*q)[kCcdMaxQuadratics], const Known& kn, double ef, const double eq[],
               int j) const {
    const double den = q == nullptr ? kn.den_low : std::max(kn.den_low, kn.sd * q[j][0] - eq[0]);
    if (!(std::fabs(f[j == 0 ? 0 : 3]) + ef <= 0.5 * delta_ * den)) return false;
    if (q == nullptr) return true;
    for (int k = 1; k < pq_.count; ++k)
      if (!((kn.inside & (1u << k)) || kn.sd * q[j][k] >= eq[k] - beta_ * den)) return false;
    return true;
  }

  /// Rule 3b at the ends of [lo, hi] (den's sign known): a near contact at lo is a hit at lo
  /// whatever the width; one at hi is a hit at lo on a leaf, or at hi - tau when the cubic
  /// restricted to [lo, hi - tau] is certainly nonzero (no coplanar instant before). Sets
  /// answer_ and returns true on a hit.
  bool near_ends(double lo, double hi, int depth, const double f[4], const double (*q)[kCcdMaxQuadratics],
                 const Known& kn, double ef, const double eq[]) {
    if (near_at(f, q, kn, ef, eq, 0)) return hit(lo);
    if (!near_at(f, q, kn, ef, eq, 2)) return false;
    const double tau = settings_.time_tolerance, w = hi - lo;
    if (w <= tau) return hit(lo);
    double fr[4];
    ccd_restrict_cubic(f, 0.0, (w - tau) / w, fr);
    const double e1 = ef_.at(depth + 1);
    const bool certain = ccd_certified_sign(fr, 4, 1, e1) != 0;
    return certain && hit(hi - tau);
  }

  bool inclusion(double lo, double hi) {
    CcdStats& st = stats_;
    st.inclusion_calls++;
    const CcdInclusionResult r = ccd_inclusion_search(s_, lo, hi, delta_, settings_.time_tolerance, settings_.max_boxes);
    st.inclusion_boxes += static_cast<unsigned long long>(r.boxes);
    if (r.capped) st.inclusion_caps++;
    if (!r.hit) return false;
    answer_ = {true, r.toi};
    return true;
  }

  const CcdSystem& s_;
  const CcdSettings& settings_;
  CcdStats& stats_;
  double delta_ = 0.0, beta_ = 0.0;
  int nodes_ = 0;
  unsigned all_inside_ = 0;  ///< the bits of every numerator
  CcdErrorBound ef_;
  CcdProjectedQuadratics pq_;
  CcdAnswer answer_;
};

}  // namespace

CcdAnswer ccd_time_search(const CcdSystem& s, const CcdSettings& settings, CcdStats& stats) {
  TimeSearch search(s, settings, stats);
  return search.run();
}

}  // namespace tecido
