#include "core/geometry/orient_predicates.h"

#include "core/geometry/expansion_arithmetic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__FAST_MATH__)
#error "orient_predicates.cpp relies on IEEE-754 rounding: do not build it with -ffast-math"
#endif
static_assert(std::numeric_limits<double>::is_iec559, "IEEE-754 doubles required");

namespace tecido {
namespace {

thread_local std::uint64_t g_exact_path_calls = 0;

// The error-free transformations and expansion arithmetic (two_sum, two_product, sum and
// scale of expansions, ...) live in expansion_arithmetic.h, shared with the plane-side sign.
using namespace expansion;

// ---------------------------------------------------------------------------------------
// Stage 3 planning: per-axis power-of-two scaling, and the check that no partial product can
// underflow. Every double on axis c is a multiple of 2^(ilogb(min nonzero |x|) - 52) (or of
// 2^-1074); after scaling by 2^s_c the axis' granularity is 2^g_c. A two_product of numbers
// that are multiples of 2^u and 2^v is exact when u + v >= -1074. The determinant multiplies
// at most one entry per axis, so every sub-product of distinct axes must satisfy it (and each
// scaled entry must stay exact, g_c >= -1074). `top`: the scaled maxima lie in
// [2^(top-1), 2^top), low enough that no partial result can overflow. Returns false when
// the expansion stage cannot be exact; the big-integer stage then runs.
template <int Cols, int Rows>
bool plan_scaling(const double (&m)[Rows][Cols], int top, int (&s)[Cols]) {
  int g[Cols];
  for (int c = 0; c < Cols; ++c) {
    double mx = 0.0, mn = std::numeric_limits<double>::infinity();
    for (int r = 0; r < Rows; ++r) {
      const double v = std::fabs(m[r][c]);
      mx = std::max(mx, v);
      if (v != 0.0) mn = std::min(mn, v);
    }
    if (mx == 0.0) return false;  // callers rule this out (equal entries give det 0)
    s[c] = top - 1 - std::ilogb(mx);
    g[c] = std::ilogb(mn) - 52 + s[c];
    if (g[c] < -1074) return false;
  }
  for (int c = 0; c < Cols; ++c)
    for (int k = c + 1; k < Cols; ++k)
      if (g[c] + g[k] < -1074) return false;
  int sum = 0;  // orient3d's products of three (for orient2d the pair check above is it)
  for (int c = 0; c < Cols; ++c) sum += g[c];
  return sum >= -1074;
}

/// Sign of det[a-d; b-d; c-d] by expansion arithmetic; inputs already scaled (no overflow,
/// no underflow possible).
int orient3d_expansion(const double* a, const double* b, const double* c, const double* d) {
  double ad[3][2], bd[3][2], cd[3][2];
  int adn[3], bdn[3], cdn[3];
  for (int k = 0; k < 3; ++k) {
    adn[k] = diff_expansion(a[k], d[k], ad[k]);
    bdn[k] = diff_expansion(b[k], d[k], bd[k]);
    cdn[k] = diff_expansion(c[k], d[k], cd[k]);
  }
  // det = ad . (bd x cd); component k of the cross product uses axes k+1 and k+2.
  double terms[3][64];
  int tn[3];
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    double p[8], q[8], minor[16];
    const int pn = mul_expansion(bdn[i], bd[i], cdn[j], cd[j], p);
    const int qn = mul_expansion(bdn[j], bd[j], cdn[i], cd[i], q);
    negate(qn, q);
    const int mn = sum_expansion(pn, p, qn, q, minor);
    tn[k] = mul_expansion(mn, minor, adn[k], ad[k], terms[k]);
  }
  double s01[128], det[192];
  const int n01 = sum_expansion(tn[0], terms[0], tn[1], terms[1], s01);
  const int n = sum_expansion(n01, s01, tn[2], terms[2], det);
  return expansion_sign(n, det);
}

/// Sign of (ax-cx)(by-cy) - (ay-cy)(bx-cx) by expansion arithmetic; inputs already scaled.
int orient2d_expansion(const double* a, const double* b, const double* c) {
  double acx[2], acy[2], bcx[2], bcy[2];
  const int acxn = diff_expansion(a[0], c[0], acx), acyn = diff_expansion(a[1], c[1], acy);
  const int bcxn = diff_expansion(b[0], c[0], bcx), bcyn = diff_expansion(b[1], c[1], bcy);
  double l[8], r[8], det[16];
  const int ln = mul_expansion(acxn, acx, bcyn, bcy, l);
  const int rn = mul_expansion(acyn, acy, bcxn, bcx, r);
  negate(rn, r);
  const int n = sum_expansion(ln, l, rn, r, det);
  return expansion_sign(n, det);
}

// ---------------------------------------------------------------------------------------
// Stage 2, between the filter and the full expansion: Shewchuk's adaptive stages B and C
// (orient2dadapt / orient3dadapt in predicates.c). B evaluates the determinant of the rounded
// differences exactly; if every difference was exact that is the answer, otherwise C adds the
// first-order corrections from the differences' round-off tails. Both carry Shewchuk's error
// bounds, which assume no underflow and no overflow; they run only on "tame" inputs, where
// every coordinate is 0 or of magnitude in [2^-250, 2^250]: every coordinate, difference and
// tail is then a multiple of 2^-302, every product of up to three of them a multiple of
// 2^-906 (no bits can be lost to underflow) and below 2^760 (no overflow).
// Returns -1, 0 or +1, or kUndecided.

constexpr int kUndecided = 2;
constexpr double kResultErrBound = (3.0 + 8.0 * 0x1p-53) * 0x1p-53;
constexpr double kCcwErrBoundB = (2.0 + 12.0 * 0x1p-53) * 0x1p-53;
constexpr double kCcwErrBoundC = (9.0 + 64.0 * 0x1p-53) * 0x1p-53 * 0x1p-53;
constexpr double kO3dErrBoundB = (3.0 + 28.0 * 0x1p-53) * 0x1p-53;
constexpr double kO3dErrBoundC = (26.0 + 288.0 * 0x1p-53) * 0x1p-53 * 0x1p-53;

inline bool tame(double v) {
  const double a = std::fabs(v);
  return a == 0.0 || (a >= 0x1p-250 && a <= 0x1p250);
}

inline double diff_tail(double a, double b, double x) {  // Shewchuk's Two_Diff_Tail
  const double bv = a - x;
  const double av = x + bv;
  return (a - av) + (bv - b);
}

inline double estimate(int n, const double* e) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += e[i];
  return s;
}

/// e = a*b - c*d exactly (length <= 4).
int two_two_diff(double a, double b, double c, double d, double* e) {
  double p[2], q[2];
  two_product(a, b, p[1], p[0]);
  two_product(c, d, q[1], q[0]);
  q[0] = -q[0];
  q[1] = -q[1];
  int pn = 0, qn = 0;
  double pz[2], qz[2];
  for (int i = 0; i < 2; ++i) {
    if (p[i] != 0.0) pz[pn++] = p[i];
    if (q[i] != 0.0) qz[qn++] = q[i];
  }
  return sum_expansion(pn, pz, qn, qz, e);
}

int orient2d_adaptive(const double* pa, const double* pb, const double* pc) {
  const double acx = pa[0] - pc[0], bcx = pb[0] - pc[0];
  const double acy = pa[1] - pc[1], bcy = pb[1] - pc[1];
  const double detsum = std::fabs(acx * bcy) + std::fabs(acy * bcx);
  double b[4];
  const int bn = two_two_diff(acx, bcy, acy, bcx, b);
  double det = estimate(bn, b);
  double errbound = kCcwErrBoundB * detsum;
  if (det >= errbound || -det >= errbound) return sign_of(det);
  const double acxtail = diff_tail(pa[0], pc[0], acx), bcxtail = diff_tail(pb[0], pc[0], bcx);
  const double acytail = diff_tail(pa[1], pc[1], acy), bcytail = diff_tail(pb[1], pc[1], bcy);
  if (acxtail == 0.0 && acytail == 0.0 && bcxtail == 0.0 && bcytail == 0.0) {
    return sign_of(det);  // the differences were exact: b is the exact determinant
  }
  errbound = kCcwErrBoundC * detsum + kResultErrBound * std::fabs(det);
  det += (acx * bcytail + bcy * acxtail) - (acy * bcxtail + bcx * acytail);
  if (det >= errbound || -det >= errbound) return sign_of(det);
  return kUndecided;
}

int orient3d_adaptive(const double* pa, const double* pb, const double* pc, const double* pd) {
  const double adx = pa[0] - pd[0], bdx = pb[0] - pd[0], cdx = pc[0] - pd[0];
  const double ady = pa[1] - pd[1], bdy = pb[1] - pd[1], cdy = pc[1] - pd[1];
  const double adz = pa[2] - pd[2], bdz = pb[2] - pd[2], cdz = pc[2] - pd[2];
  const double permanent = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * std::fabs(adz) +
                           (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * std::fabs(bdz) +
                           (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * std::fabs(cdz);
  double bc[4], ca[4], ab[4];
  const int bcn = two_two_diff(bdx, cdy, cdx, bdy, bc);
  const int can = two_two_diff(cdx, ady, adx, cdy, ca);
  const int abn = two_two_diff(adx, bdy, bdx, ady, ab);
  double adet[8], bdet[8], cdet[8], abdet[16], fin[24];
  const int an = scale_expansion(bcn, bc, adz, adet);
  const int bn = scale_expansion(can, ca, bdz, bdet);
  const int cn = scale_expansion(abn, ab, cdz, cdet);
  const int abn2 = sum_expansion(an, adet, bn, bdet, abdet);
  const int fn = sum_expansion(abn2, abdet, cn, cdet, fin);
  double det = estimate(fn, fin);
  double errbound = kO3dErrBoundB * permanent;
  if (det >= errbound || -det >= errbound) return sign_of(det);
  const double adxtail = diff_tail(pa[0], pd[0], adx), bdxtail = diff_tail(pb[0], pd[0], bdx);
  const double cdxtail = diff_tail(pc[0], pd[0], cdx), adytail = diff_tail(pa[1], pd[1], ady);
  const double bdytail = diff_tail(pb[1], pd[1], bdy), cdytail = diff_tail(pc[1], pd[1], cdy);
  const double adztail = diff_tail(pa[2], pd[2], adz), bdztail = diff_tail(pb[2], pd[2], bdz);
  const double cdztail = diff_tail(pc[2], pd[2], cdz);
  if (adxtail == 0.0 && bdxtail == 0.0 && cdxtail == 0.0 && adytail == 0.0 && bdytail == 0.0 &&
      cdytail == 0.0 && adztail == 0.0 && bdztail == 0.0 && cdztail == 0.0) {
    return sign_of(det);  // the differences were exact: fin is the exact determinant
  }
  errbound = kO3dErrBoundC * permanent + kResultErrBound * std::fabs(det);
  det += (adz * ((bdx * cdytail + cdy * bdxtail) - (bdy * cdxtail + cdx * bdytail)) +
          adztail * (bdx * cdy - bdy * cdx)) +
         (bdz * ((cdx * adytail + ady * cdxtail) - (cdy * adxtail + adx * cdytail)) +
          bdztail * (cdx * ady - cdy * adx)) +
         (cdz * ((adx * bdytail + bdy * adxtail) - (ady * bdxtail + bdx * adytail)) +
          cdztail * (adx * bdy - ady * bdx));
  if (det >= errbound || -det >= errbound) return sign_of(det);
  return kUndecided;
}

// ---------------------------------------------------------------------------------------
// Stage 4: the (K+1)x(K+1) determinant [coords | 1] as a sum of (K+1)! signed monomials,
// each a product of K doubles = (product of 53-bit integers) * 2^(sum of exponents), added
// exactly into a fixed-width two's-complement big integer.

/// |x| = m * 2^e with m < 2^53 an integer; x finite and nonzero.
inline void decompose(double x, std::uint64_t& m, int& e) {
  int k;
  const double f = std::frexp(std::fabs(x), &k);  // f in [0.5, 1)
  m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  e = k - 53;  // in [-1126, 971]
}

template <int K>
int bigint_det_sign(const double (&rows)[K + 1][K]) {
  using u128 = unsigned __int128;
  constexpr int kExpSpan = 971 + 1126;                // range of e in decompose()
  constexpr int kWords = (K * kExpSpan) / 64 + K + 4;  // shift + mantissa + carries
  struct Term {
    bool neg;
    std::uint64_t w[3];
    int e;
  };
  Term terms[24];
  int nt = 0;
  int perm[K + 1];
  for (int i = 0; i <= K; ++i) perm[i] = i;
  do {
    int inversions = 0;
    for (int i = 0; i <= K; ++i)
      for (int j = i + 1; j <= K; ++j) inversions += perm[i] > perm[j];
    bool neg = (inversions % 2) != 0;
    std::uint64_t mant[K];
    int e = 0, nf = 0;
    bool zero = false;
    for (int r = 0; r <= K; ++r) {
      if (perm[r] == K) continue;  // the column of ones
      const double v = rows[r][perm[r]];
      if (v == 0.0) {
        zero = true;
        break;
      }
      if (v < 0.0) neg = !neg;
      int ev;
      decompose(v, mant[nf++], ev);
      e += ev;
    }
    if (zero) continue;
    Term& t = terms[nt++];
    t.neg = neg;
    t.e = e;
    const u128 p = static_cast<u128>(mant[0]) * mant[1];  // < 2^106
    if constexpr (K == 2) {
      t.w[0] = static_cast<std::uint64_t>(p);
      t.w[1] = static_cast<std::uint64_t>(p >> 64);
      t.w[2] = 0;
    } else {
      const u128 lo = static_cast<u128>(static_cast<std::uint64_t>(p)) * mant[2];
      const u128 hi = static_cast<u128>(static_cast<std::uint64_t>(p >> 64)) * mant[2];
      const u128 mid = (lo >> 64) + static_cast<std::uint64_t>(hi);
      t.w[0] = static_cast<std::uint64_t>(lo);
      t.w[1] = static_cast<std::uint64_t>(mid);
      t.w[2] = static_cast<std::uint64_t>(mid >> 64) + static_cast<std::uint64_t>(hi >> 64);
    }
  } while (std::next_permutation(perm, perm + K + 1));
  if (nt == 0) return 0;

  int emin = terms[0].e;
  for (int i = 1; i < nt; ++i) emin = std::min(emin, terms[i].e);
  // One two's-complement accumulator, wide enough for the sum and its sign bit.
  std::uint64_t acc[kWords] = {};
  for (int i = 0; i < nt; ++i) {
    const Term& t = terms[i];
    const int shift = t.e - emin;
    const int wi = shift / 64, b = shift % 64;
    std::uint64_t v[4];
    if (b == 0) {
      v[0] = t.w[0];
      v[1] = t.w[1];
      v[2] = t.w[2];
      v[3] = 0;
    } else {
      v[0] = t.w[0] << b;
      v[1] = (t.w[1] << b) | (t.w[0] >> (64 - b));
      v[2] = (t.w[2] << b) | (t.w[1] >> (64 - b));
      v[3] = t.w[2] >> (64 - b);
    }
    // acc += v * 2^(64 wi) or acc -= v * 2^(64 wi), the carry / borrow running to the top.
    std::uint64_t c = 0;
    for (int k = wi; k < kWords; ++k) {
      const std::uint64_t x = k - wi < 4 ? v[k - wi] : 0;
      if (k - wi >= 4 && c == 0) break;
      const u128 y = static_cast<u128>(x) + c;
      if (!t.neg) {
        const u128 s = acc[k] + y;
        acc[k] = static_cast<std::uint64_t>(s);
        c = static_cast<std::uint64_t>(s >> 64);
      } else {
        c = static_cast<u128>(acc[k]) < y ? 1 : 0;
        acc[k] = static_cast<std::uint64_t>(acc[k] - y);
      }
    }
  }
  if (static_cast<std::int64_t>(acc[kWords - 1]) < 0) return -1;
  for (int k = kWords - 1; k >= 0; --k)
    if (acc[k] != 0) return 1;
  return 0;
}

}  // namespace

std::uint64_t orient_exact_path_count() { return g_exact_path_calls; }

namespace detail {

int orient3d_sign_bigint(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double rows[4][3] = {{a[0], a[1], a[2]}, {b[0], b[1], b[2]},
                             {c[0], c[1], c[2]}, {d[0], d[1], d[2]}};
  return bigint_det_sign<3>(rows);
}

int orient2d_sign_bigint(double ax, double ay, double bx, double by, double cx, double cy) {
  const double rows[3][2] = {{ax, ay}, {bx, by}, {cx, cy}};
  return bigint_det_sign<2>(rows);
}

int orient3d_sign_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  ++g_exact_path_calls;
  // Exact zeros first (cheap, and common in meshes): two equal points, or an axis on which
  // all four points agree (the column of differences is then exactly zero).
  if (a == b || a == c || a == d || b == c || b == d || c == d) return 0;
  for (int k = 0; k < 3; ++k)
    if (a[k] == d[k] && b[k] == d[k] && c[k] == d[k]) return 0;
  double m[4][3] = {{a[0], a[1], a[2]}, {b[0], b[1], b[2]},
                    {c[0], c[1], c[2]}, {d[0], d[1], d[2]}};
  bool all_tame = true;
  for (const auto& row : m)
    for (double v : row) all_tame &= tame(v);
  if (all_tame) {
    const int r = orient3d_adaptive(m[0], m[1], m[2], m[3]);
    if (r != kUndecided) return r;
  }
  int s[3];
  // Scaled maxima below 2^336: |det| < 2^(3*337+3) stays far from overflow.
  if (!plan_scaling<3, 4>(m, 336, s)) return bigint_det_sign<3>(m);
  for (auto& row : m)
    for (int k = 0; k < 3; ++k) row[k] = std::ldexp(row[k], s[k]);  // exact (see plan)
  return orient3d_expansion(m[0], m[1], m[2], m[3]);
}

int orient2d_sign_exact(double ax, double ay, double bx, double by, double cx, double cy) {
  ++g_exact_path_calls;
  if ((ax == bx && ay == by) || (ax == cx && ay == cy) || (bx == cx && by == cy)) return 0;
  if ((ax == cx && bx == cx) || (ay == cy && by == cy)) return 0;
  double m[3][2] = {{ax, ay}, {bx, by}, {cx, cy}};
  if (tame(ax) && tame(ay) && tame(bx) && tame(by) && tame(cx) && tame(cy)) {
    const int r = orient2d_adaptive(m[0], m[1], m[2]);
    if (r != kUndecided) return r;
  }
  int s[2];
  if (!plan_scaling<2, 3>(m, 500, s)) return bigint_det_sign<2>(m);
  for (auto& row : m)
    for (int k = 0; k < 2; ++k) row[k] = std::ldexp(row[k], s[k]);
  return orient2d_expansion(m[0], m[1], m[2]);
}

}  // namespace detail

}  // namespace tecido
