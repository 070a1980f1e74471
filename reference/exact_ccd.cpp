// The only translation unit that includes GMP (gmpxx; reference/CMakeLists.txt links gmpxx and
// gmp privately). The exact continuous-collision referee, in four parts:
//   1. integer polynomials in t (mpz coefficients): arithmetic, gcd, square-free part, signs at
//      rationals, and Bernstein coefficient signs on an interval;
//   2. real algebraic numbers in [0, 1] given by a square-free polynomial and an isolating
//      interval: isolation, sign of another polynomial there, comparison, rounding to doubles;
//   3. the input scaled to integers (doubles and decimal rationals);
//   4. the contact conditions (vertex-face, edge-edge, vertex-edge) and the earliest contact.
// Why it is exact: every decision is the sign of an integer polynomial at a rational (computed
// exactly), at an algebraic number (proven by Bernstein coefficients of one strict sign on an
// isolating interval, or zero by a common factor with the number's defining polynomial), or the
// order of two algebraic numbers (disjoint intervals, or equality proven by a common factor with
// a single root on the union). No step rounds.
#include "reference/exact_ccd.h"

#include "reference/exact_ccd_feature_contact.h"
#include "reference/exact_ccd_filter.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

namespace tecido::reference {
namespace {

using Z = mpz_class;
using Q = mpq_class;

// ---------------------------------------------------------------------------------------------
// 1. Integer polynomials in t
// ---------------------------------------------------------------------------------------------

/// c[i] is the coefficient of t^i; no trailing zeros (the zero polynomial is empty).
struct Poly {
  std::vector<Z> c;
};

void trim(Poly& p) {
  while (!p.c.empty() && p.c.back() == 0) p.c.pop_back();
}
int degree(const Poly& p) { return static_cast<int>(p.c.size()) - 1; }
bool is_zero(const Poly& p) { return p.c.empty(); }

// (In-place GMP calls below avoid temporaries: allocation dominates the cost at these sizes.)
Poly operator+(Poly a, const Poly& b) {
  if (a.c.size() < b.c.size()) a.c.resize(b.c.size());
  for (std::size_t i = 0; i < b.c.size(); ++i) mpz_add(a.c[i].get_mpz_t(), a.c[i].get_mpz_t(), b.c[i].get_mpz_t());
  trim(a);
  return a;
}
Poly operator-(Poly a, const Poly& b) {
  if (a.c.size() < b.c.size()) a.c.resize(b.c.size());
  for (std::size_t i = 0; i < b.c.size(); ++i) mpz_sub(a.c[i].get_mpz_t(), a.c[i].get_mpz_t(), b.c[i].get_mpz_t());
  trim(a);
  return a;
}
Poly operator*(const Poly& a, const Poly& b) {
  if (is_zero(a) || is_zero(b)) return {};
  Poly r;
  r.c.resize(a.c.size() + b.c.size() - 1);
  for (std::size_t i = 0; i < a.c.size(); ++i)
    for (std::size_t j = 0; j < b.c.size(); ++j)
      mpz_addmul(r.c[i + j].get_mpz_t(), a.c[i].get_mpz_t(), b.c[j].get_mpz_t());
  trim(r);
  return r;
}

Poly derivative(const Poly& p) {
  Poly r;
  for (std::size_t i = 1; i < p.c.size(); ++i) r.c.push_back(p.c[i] * static_cast<unsigned long>(i));
  trim(r);
  return r;
}

/// p divided by the gcd of its coefficients, leading coefficient made positive.
Poly primitive(Poly p) {
  if (is_zero(p)) return p;
  Z g = 0;
  for (const Z& x : p.c) g = gcd(g, x);
  if (p.c.back() < 0) g = -g;
  for (Z& x : p.c) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
  return p;
}

/// lc(b)^k times the remainder of a by b (b != 0): same zeros, integer arithmetic only.
Poly pseudo_remainder(Poly a, const Poly& b) {
  const int db = degree(b);
  while (degree(a) >= db) {
    const int shift = degree(a) - db;
    const Z la = a.c.back();
    for (Z& x : a.c) x *= b.c.back();
    for (int i = 0; i <= db; ++i) a.c[static_cast<std::size_t>(i + shift)] -= la * b.c[static_cast<std::size_t>(i)];
    trim(a);
  }
  return a;
}

/// The greatest common divisor of a and b (primitive, positive leading coefficient; the zero
/// polynomial when both are zero). Euclid's algorithm on primitive pseudo-remainders.
Poly gcd(Poly a, Poly b) {
  a = primitive(std::move(a));
  b = primitive(std::move(b));
  while (!is_zero(b)) {
    Poly r = primitive(pseudo_remainder(a, b));
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}

/// a / b for a primitive b dividing a over the rationals (then over the integers, Gauss).
Poly divide_exactly(Poly a, const Poly& b) {
  const int db = degree(b);
  Poly q;
  q.c.assign(static_cast<std::size_t>(std::max(degree(a) - db + 1, 0)), Z(0));
  while (degree(a) >= db) {
    const int shift = degree(a) - db;
    Z k;
    mpz_divexact(k.get_mpz_t(), a.c.back().get_mpz_t(), b.c.back().get_mpz_t());
    q.c[static_cast<std::size_t>(shift)] = k;
    for (int i = 0; i <= db; ++i) a.c[static_cast<std::size_t>(i + shift)] -= k * b.c[static_cast<std::size_t>(i)];
    trim(a);
  }
  if (!is_zero(a)) throw std::logic_error("exact_ccd: inexact polynomial division");
  trim(q);
  return q;
}

/// The square-free part of a non-zero p: same roots, each simple (p / gcd(p, p')).
Poly square_free(const Poly& p) {
  const Poly g = gcd(p, derivative(p));
  return degree(g) <= 0 ? primitive(p) : primitive(divide_exactly(primitive(p), g));
}

/// The sign of p(num/den), den > 0: of den^d p(num/den) = sum c_i num^i den^(d-i) (Horner).
int sign_at(const Poly& p, const Q& t) {
  if (is_zero(p)) return 0;
  const Z& num = t.get_num();
  const Z& den = t.get_den();
  Z v = p.c.back(), power = den;
  for (int i = degree(p) - 1; i >= 0; --i) {
    mpz_mul(v.get_mpz_t(), v.get_mpz_t(), num.get_mpz_t());
    mpz_addmul(v.get_mpz_t(), p.c[static_cast<std::size_t>(i)].get_mpz_t(), power.get_mpz_t());
    if (i > 0) mpz_mul(power.get_mpz_t(), power.get_mpz_t(), den.get_mpz_t());
  }
  return sgn(v);
}

/// The signs of p's Bernstein coefficients on [l, r] (l < r), as the coefficients of
/// (1 + x)^d p((l + r x) / (1 + x)) = sum_k C(d, k) b_k x^k: with l = L/D, r = R/D,
/// sum_i c_i (L + R x)^i (D + D x)^(d-i).
std::vector<int> bernstein_signs(const Poly& p, const Q& l, const Q& r) {
  const int d = degree(p);
  Z D;
  mpz_lcm(D.get_mpz_t(), l.get_den().get_mpz_t(), r.get_den().get_mpz_t());
  const Z L = l.get_num() * (D / l.get_den()), R = r.get_num() * (D / r.get_den());
  std::vector<Poly> a_pow{Poly{{Z(1)}}}, b_pow{Poly{{Z(1)}}};
  for (int i = 1; i <= d; ++i) {
    a_pow.push_back(a_pow.back() * Poly{{L, R}});
    b_pow.push_back(b_pow.back() * Poly{{D, D}});
  }
  Poly sum;
  for (int i = 0; i <= d; ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    sum = sum + Poly{{p.c[ui]}} * a_pow[ui] * b_pow[static_cast<std::size_t>(d - i)];
  }
  std::vector<int> s(static_cast<std::size_t>(d + 1), 0);
  for (std::size_t k = 0; k < sum.c.size(); ++k) s[k] = sgn(sum.c[k]);
  return s;
}

/// Sign changes in the sequence, zeros skipped (Descartes' bound on the roots in (l, r)).
int variations(const std::vector<int>& s) {
  int v = 0, last = 0;
  for (int x : s)
    if (x != 0) {
      v += last != 0 && x != last;
      last = x;
    }
  return v;
}

/// +1 or -1 when every coefficient has that strict sign (then so has p on [l, r]), else 0.
int strict_sign(const std::vector<int>& s) {
  for (int x : s)
    if (x == 0 || x != s.front()) return 0;
  return s.empty() ? 0 : s.front();
}

// ---------------------------------------------------------------------------------------------
// 2. Real algebraic numbers in [0, 1]
// ---------------------------------------------------------------------------------------------

/// Caps the refinement loops, which terminate by construction; reaching it is a bug, reported
/// rather than hanging a suite.
constexpr int kMaxRefinements = 200000;

/// A real number in [0, 1]: either the rational lo (exact), or the only root of the square-free
/// polynomial g in the open interval (lo, hi), with g(lo), g(hi) non-zero of opposite signs.
struct Root {
  std::shared_ptr<const Poly> g;
  Q lo, hi;
  bool exact = false;
  int sign_lo = 0;  ///< sign of g(lo) when !exact
};

Root rational_root(const Q& x) {
  Root r;
  r.lo = r.hi = x;
  r.exact = true;
  return r;
}

/// Narrows the root's interval at s, lo < s < hi (it becomes exact when g(s) = 0).
void split(Root& r, const Q& s) {
  const int sg = sign_at(*r.g, s);
  if (sg == 0) {
    r = rational_root(s);
  } else if (sg == r.sign_lo) {
    r.lo = s;
  } else {
    r.hi = s;
  }
}
void bisect(Root& r) { split(r, Q((r.lo + r.hi) / 2)); }

void isolate_in(const std::shared_ptr<const Poly>& g, const Q& l, const Q& r, std::vector<Root>& out) {
  const int v = variations(bernstein_signs(*g, l, r));
  if (v == 0) return;
  const int sl = sign_at(*g, l), sr = sign_at(*g, r);
  if (v == 1 && sl != 0 && sr != 0) {  // Descartes: exactly one root in (l, r)
    Root root;
    root.g = g;
    root.lo = l;
    root.hi = r;
    root.sign_lo = sl;
    out.push_back(std::move(root));
    return;
  }
  const Q m = (l + r) / 2;
  isolate_in(g, l, m, out);
  if (sign_at(*g, m) == 0) out.push_back(rational_root(m));
  isolate_in(g, m, r, out);
}

/// The real roots of p (non-zero) in [0, 1], in increasing order. Method: square-free part, then
/// Descartes' rule of signs on Bernstein coefficients with bisection (Collins and Akritas 1976,
/// in the Bernstein form of Lane and Riesenfeld 1981).
std::vector<Root> roots_in_unit_interval(const Poly& p) {
  std::vector<Root> out;
  if (degree(p) < 1) return out;
  const auto g = std::make_shared<const Poly>(square_free(p));
  if (sign_at(*g, Q(0)) == 0) out.push_back(rational_root(Q(0)));
  isolate_in(g, Q(0), Q(1), out);
  if (sign_at(*g, Q(1)) == 0) out.push_back(rational_root(Q(1)));
  return out;
}

/// Whether the (square-free part of the) divisor d of r.g vanishes at r: d then has one simple
/// root in r's interval or none, told by its signs at the ends.
bool vanishes_at(const Poly& d, const Root& r) { return degree(d) >= 1 && sign_at(d, r.lo) != sign_at(d, r.hi); }

/// The sign of h at the root, refining the root's interval as needed (a zero is recognised by
/// the common factor, looked for after two refinements: most signs are not zero).
int sign_at(const Poly& h, Root& r) {
  if (is_zero(h)) return 0;
  for (int i = 0; i < kMaxRefinements; ++i) {  // terminates: a non-zero sign shows on a small interval
    if (r.exact) return sign_at(h, r.lo);
    const int s = strict_sign(bernstein_signs(h, r.lo, r.hi));
    if (s != 0) return s;
    if (i == 2 && vanishes_at(gcd(*r.g, h), r)) return 0;
    bisect(r);
  }
  throw std::logic_error("exact_ccd: sign refinement did not terminate");
}

/// The sign of (root - s) for a rational s.
int compare(Root& r, const Q& s) {
  if (r.exact) return sgn(r.lo - s);
  if (s <= r.lo) return 1;
  if (s >= r.hi) return -1;
  const int sg = sign_at(*r.g, s);
  if (sg == 0) return 0;
  return sg == r.sign_lo ? 1 : -1;  // no sign change on (lo, s]: the root is past s
}

/// The sign of (a - b). Unequal numbers are separated by refining both intervals; equal ones
/// are recognised as the single root of the common factor d = gcd(ga, gb) on the union of
/// their (overlapping) intervals (Descartes' count 1 there).
int compare(Root& a, Root& b) {
  if (a.exact) return -compare(b, a.lo);
  if (b.exact) return compare(a, b.lo);
  const Poly d = gcd(*a.g, *b.g);
  const bool maybe_equal = vanishes_at(d, a) && vanishes_at(d, b);
  for (int i = 0; i < kMaxRefinements; ++i) {
    if (a.exact) return -compare(b, a.lo);
    if (b.exact) return compare(a, b.lo);
    if (a.hi <= b.lo) return -1;
    if (b.hi <= a.lo) return 1;
    if (maybe_equal && variations(bernstein_signs(d, std::min(a.lo, b.lo), std::max(a.hi, b.hi))) == 1) return 0;
    bisect(a);
    bisect(b);
  }
  throw std::logic_error("exact_ccd: comparison did not terminate");
}

/// The largest double <= q, for 0 <= q <= 1 (mpq_get_d truncates; corrected exactly).
double floor_double(const Q& q) {
  double d = q.get_d();
  while (Q(d) > q) d = std::nextafter(d, -1.0);
  while (Q(std::nextafter(d, 2.0)) <= q) d = std::nextafter(d, 2.0);
  return d;
}

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
double from_bits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

/// The answer for a rational contact time x in [0, 1].
ExactCcd answer_at(const Q& x) {
  ExactCcd out;
  out.hit = true;
  out.toi_lo = floor_double(x);
  if (Q(out.toi_lo) == x) {
    out.toi = out.toi_hi = out.toi_lo;
    out.toi_exact = true;
    return out;
  }
  out.toi_hi = std::nextafter(out.toi_lo, 2.0);
  const int c = sgn(x - (Q(out.toi_lo) + Q(out.toi_hi)) / 2);
  out.toi = c < 0 ? out.toi_lo : c > 0 ? out.toi_hi : ((bits(out.toi_lo) & 1) ? out.toi_hi : out.toi_lo);
  return out;
}

/// The answer for a contact at the root: its interval narrowed at doubles (bisection on bit
/// patterns, which order non-negative doubles) until it holds none, then rounded by comparing
/// the root with the exact midpoint of the two doubles around it.
ExactCcd answer_at(Root& r) {
  for (int i = 0; i < 80 && !r.exact; ++i) {
    const double below = floor_double(r.lo);
    const double first = std::nextafter(below, 2.0);  // smallest double > lo
    const double h = floor_double(r.hi);
    const double last = Q(h) == r.hi ? std::nextafter(h, -1.0) : h;  // largest double < hi
    if (first > last) {
      ExactCcd out;
      out.hit = true;
      out.toi_lo = below;
      out.toi_hi = first;
      const int c = compare(r, Q(Q(below) + Q(first)) / 2);
      out.toi = c < 0 ? below : c > 0 ? first : ((bits(below) & 1) ? first : below);
      return out;
    }
    split(r, Q(from_bits(bits(first) + (bits(last) - bits(first)) / 2)));
  }
  if (!r.exact) throw std::logic_error("exact_ccd: rounding did not terminate");
  return answer_at(r.lo);
}

// ---------------------------------------------------------------------------------------------
// 3. The input as integers
// ---------------------------------------------------------------------------------------------

/// Integer coordinates: the query's coordinates times one positive factor (contact times do not
/// change under a uniform scaling of space).
struct IntQuery {
  CcdKind kind = CcdKind::VertexFace;
  std::array<std::array<Z, 3>, 4> x0, x1;
};

/// The doubles as integers: each is M 2^E with an integer M (|M| < 2^53); all are multiplied
/// by 2^-Emin, the smallest E among the non-zero ones.
IntQuery integer_query(const CcdQuery& q) {
  long e_min = std::numeric_limits<long>::max();
  std::array<std::array<std::pair<std::int64_t, long>, 3>, 8> me;
  for (int s = 0; s < 8; ++s)
    for (int k = 0; k < 3; ++k) {
      const double x = (s < 4 ? q.x0[static_cast<std::size_t>(s)] : q.x1[static_cast<std::size_t>(s - 4)])[k];
      if (!std::isfinite(x)) throw std::domain_error("exact_ccd: non-finite coordinate");
      int e = 0;
      const double m = std::frexp(x, &e);
      me[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)] = {static_cast<std::int64_t>(std::ldexp(m, 53)),
                                                                      e - 53L};
      if (x != 0) e_min = std::min(e_min, e - 53L);
    }
  IntQuery out;
  out.kind = q.kind;
  for (std::size_t s = 0; s < 8; ++s)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [m, e] = me[s][k];
      Z v(static_cast<long>(m));
      if (m != 0) mpz_mul_2exp(v.get_mpz_t(), v.get_mpz_t(), static_cast<mp_bitcnt_t>(e - e_min));
      (s < 4 ? out.x0[s] : out.x1[s - 4])[k] = v;
    }
  return out;
}

/// A decimal integer: an optional sign and at least one digit, nothing else.
Z parse_integer(const std::string& s) {
  const std::size_t start = (!s.empty() && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
  if (s.size() == start) throw std::invalid_argument("exact_ccd: empty integer '" + s + "'");
  for (std::size_t i = start; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') throw std::invalid_argument("exact_ccd: malformed integer '" + s + "'");
  return Z(s.substr(start), 10) * (s[0] == '-' ? -1 : 1);
}

Q parse_rational(const RationalCoord& c) {
  const Z den = parse_integer(c.den);
  if (den == 0) throw std::invalid_argument("exact_ccd: zero denominator in " + c.num + "/" + c.den);
  Q q(parse_integer(c.num), den);
  q.canonicalize();
  return q;
}

/// The 24 coordinates of a rational query, parsed: [0..3] at t = 0, [4..7] at t = 1.
using RationalPoints = std::array<std::array<Q, 3>, 8>;

RationalPoints parse_query(const RationalCcdQuery& q) {
  RationalPoints v;
  for (std::size_t s = 0; s < 8; ++s)
    for (std::size_t k = 0; k < 3; ++k) v[s][k] = parse_rational(s < 4 ? q.x0[s][k] : q.x1[s - 4][k]);
  return v;
}

/// The rationals as integers: all multiplied by the lcm of their denominators.
IntQuery integer_query(CcdKind kind, const RationalPoints& v) {
  Z lcm = 1;
  for (const auto& p : v)
    for (const Q& c : p) mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), c.get_den().get_mpz_t());
  IntQuery out;
  out.kind = kind;
  for (std::size_t s = 0; s < 8; ++s)
    for (std::size_t k = 0; k < 3; ++k)
      (s < 4 ? out.x0[s] : out.x1[s - 4])[k] = v[s][k].get_num() * (lcm / v[s][k].get_den());
  return out;
}

/// q as a double when it is exactly one: a power-of-two denominator (canonical form), an odd
/// part of at most 53 bits, and exponents within the double range (subnormals included).
std::optional<double> exact_double(const Q& q) {
  const Z& num = q.get_num();
  const Z& den = q.get_den();
  if (num == 0) return 0.0;
  if (mpz_popcount(den.get_mpz_t()) != 1) return std::nullopt;
  const long k = static_cast<long>(mpz_scan1(den.get_mpz_t(), 0));                  // den = 2^k
  const long low = static_cast<long>(mpz_scan1(num.get_mpz_t(), 0)) - k;            // lowest bit's exponent
  const long high = static_cast<long>(mpz_sizeinbase(num.get_mpz_t(), 2)) - 1 - k;  // highest bit's
  if (high - low >= 53 || low < -1074 || high > 1023) return std::nullopt;
  return q.get_d();  // exact: q is representable
}

/// The double nearest to q (ties to even, +-infinity past the largest double).
double nearest(const Q& q) {
  if (q < 0) return -nearest(Q(-q));
  Q two_1024 = 1;
  mpq_mul_2exp(two_1024.get_mpq_t(), two_1024.get_mpq_t(), 1024);
  if (q >= two_1024) return std::numeric_limits<double>::infinity();
  double d = q.get_d();  // truncated
  while (Q(d) > q) d = std::nextafter(d, -1.0);
  const double next = std::nextafter(d, std::numeric_limits<double>::infinity());
  const Q next_q = std::isinf(next) ? two_1024 : Q(next);
  if (Q(d) == q) return d;
  const int c = sgn(Q(q - d) - Q(next_q - q));
  return c < 0 ? d : c > 0 ? next : ((bits(d) & 1) ? next : d);
}

// ---------------------------------------------------------------------------------------------
// 4. Contact conditions and the earliest contact
// ---------------------------------------------------------------------------------------------

/// A point moving linearly: three polynomials of degree <= 1.
struct PV {
  Poly x, y, z;
};
PV operator-(const PV& a, const PV& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PV cross(const PV& a, const PV& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Poly dot(const PV& a, const PV& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

std::array<PV, 4> moving_points(const IntQuery& q) {
  std::array<PV, 4> out;
  for (std::size_t i = 0; i < 4; ++i) {
    Poly c[3];
    for (std::size_t k = 0; k < 3; ++k) {
      c[k].c = {q.x0[i][k], q.x1[i][k] - q.x0[i][k]};
      trim(c[k]);
    }
    out[i] = {c[0], c[1], c[2]};
  }
  return out;
}

bool zero_at(const PV& v, Root& t) { return sign_at(v.x, t) == 0 && sign_at(v.y, t) == 0 && sign_at(v.z, t) == 0; }

/// Whether p lies on the closed segment [u, v] at t: (p - u) x (v - u) = 0 and
/// (p - u).(p - v) <= 0 (for u = v: p = u).
bool on_segment(const PV& p, const PV& u, const PV& v, Root& t) {
  return zero_at(cross(p - u, v - u), t) && sign_at(dot(p - u, p - v), t) <= 0;
}

/// Whether the vertex p lies in the closed triangle abc at t, given that the four points are
/// coplanar at t. Non-degenerate triangle (n = (b-a) x (c-a) != 0): ((v-u) x (p-u)).n >= 0 on
/// the three edges u -> v. Degenerate (collinear or coincident corners): the triangle is the
/// union of its edges.
bool vertex_in_triangle(const PV& p, const PV& a, const PV& b, const PV& c, Root& t) {
  const PV n = cross(b - a, c - a);
  if (zero_at(n, t)) return on_segment(p, a, b, t) || on_segment(p, b, c, t) || on_segment(p, c, a, t);
  return sign_at(dot(cross(b - a, p - a), n), t) >= 0 && sign_at(dot(cross(c - b, p - b), n), t) >= 0 &&
         sign_at(dot(cross(a - c, p - c), n), t) >= 0;
}

/// Whether the closed segments [a0, a1] and [b0, b1] meet at t, given that they are coplanar at
/// t. Not parallel (m = da x db != 0): the lines cross at a0 + u da = b0 + v db with
/// u = ((b0-a0) x db).m / m.m and v = ((b0-a0) x da).m / m.m, both in [0, 1]. Parallel,
/// collinear or degenerate: they meet iff an end point of one lies on the other.
bool segments_meet(const PV& a0, const PV& a1, const PV& b0, const PV& b1, Root& t) {
  const PV da = a1 - a0, db = b1 - b0, w = b0 - a0, m = cross(da, db);
  if (zero_at(m, t))
    return on_segment(a0, b0, b1, t) || on_segment(a1, b0, b1, t) || on_segment(b0, a0, a1, t) ||
           on_segment(b1, a0, a1, t);
  const Poly mm = dot(m, m), nu = dot(cross(w, db), m), nv = dot(cross(w, da), m);
  return sign_at(nu, t) >= 0 && sign_at(mm - nu, t) >= 0 && sign_at(nv, t) >= 0 && sign_at(mm - nv, t) >= 0;
}

/// The earliest t in [0, 1] at which p lies on the closed segment [u, v]. The three components
/// of c = (p - u) x (v - u) vanish together at the roots of their gcd; when c is identically
/// zero (p, u, v collinear throughout) the condition is e = (p - u).(p - v) <= 0 alone, first
/// met at t = 0 or at a root of e.
std::optional<Root> earliest_on_segment(const PV& p, const PV& u, const PV& v) {
  const PV c = cross(p - u, v - u);
  const Poly e = dot(p - u, p - v);
  const Poly g = gcd(gcd(c.x, c.y), c.z);
  if (is_zero(g)) {
    if (sign_at(e, Q(0)) <= 0) return rational_root(Q(0));
    std::vector<Root> r = roots_in_unit_interval(e);
    if (r.empty()) return std::nullopt;
    return r.front();
  }
  for (Root& t : roots_in_unit_interval(g))
    if (sign_at(e, t) <= 0) return t;
  return std::nullopt;
}

/// The coplanarity cubic: det[b - a, c - a, p - a] (vertex p, triangle abc) or
/// det[a1 - a0, b1 - b0, b0 - a0] (edges a0a1, b0b1); contact at t needs it to vanish.
Poly coplanarity_cubic(CcdKind kind, const std::array<PV, 4>& x) {
  if (kind == CcdKind::VertexFace) return dot(cross(x[2] - x[1], x[3] - x[1]), x[0] - x[1]);
  return dot(cross(x[1] - x[0], x[3] - x[2]), x[2] - x[0]);
}

/// The earliest of the candidate contact times.
std::optional<Root> earliest_of(std::vector<std::optional<Root>> candidates) {
  std::optional<Root> best;
  for (auto& c : candidates)
    if (c && (!best || compare(*c, *best) < 0)) best = std::move(c);
  return best;
}

/// The earliest contact when the coplanarity cubic f is not identically zero: contact needs
/// f(t) = 0, so it is the first root of f in [0, 1] at which the primitives touch.
template <class Touches>
std::optional<Root> first_root_touching(const Poly& f, Touches touches) {
  for (Root& t : roots_in_unit_interval(f))
    if (touches(t)) return t;
  return std::nullopt;
}

/// Vertex-face. When the four points are coplanar throughout (f = 0), the earliest contact
/// after t = 0 has the vertex on the triangle's boundary (strict inside conditions would hold a
/// moment earlier too), that is on one of its closed edges, also when the triangle is degenerate
/// then: the earliest of three vertex-edge problems.
std::optional<Root> earliest_vertex_face(const IntQuery& q) {
  const auto x = moving_points(q);
  const PV &p = x[0], &a = x[1], &b = x[2], &c = x[3];
  const Poly f = coplanarity_cubic(CcdKind::VertexFace, x);
  auto touches = [&](Root& t) { return vertex_in_triangle(p, a, b, c, t); };
  if (!is_zero(f)) return first_root_touching(f, touches);
  Root zero = rational_root(Q(0));
  if (touches(zero)) return zero;
  return earliest_of({earliest_on_segment(p, a, b), earliest_on_segment(p, b, c), earliest_on_segment(p, c, a)});
}

/// Edge-edge. Coplanar throughout: the earliest contact after t = 0 has an end point of one
/// segment on the other (interior crossings of non-parallel segments persist a moment earlier;
/// parallel segments meet at an end point), the earliest of four vertex-edge problems.
std::optional<Root> earliest_edge_edge(const IntQuery& q) {
  const auto x = moving_points(q);
  const PV &a0 = x[0], &a1 = x[1], &b0 = x[2], &b1 = x[3];
  const Poly f = coplanarity_cubic(CcdKind::EdgeEdge, x);
  auto touches = [&](Root& t) { return segments_meet(a0, a1, b0, b1, t); };
  if (!is_zero(f)) return first_root_touching(f, touches);
  Root zero = rational_root(Q(0));
  if (touches(zero)) return zero;
  return earliest_of({earliest_on_segment(a0, b0, b1), earliest_on_segment(a1, b0, b1), earliest_on_segment(b0, a0, a1),
                      earliest_on_segment(b1, a0, a1)});
}

ExactCcd solve(const IntQuery& q) {
  std::optional<Root> t = q.kind == CcdKind::VertexFace ? earliest_vertex_face(q) : earliest_edge_edge(q);
  if (!t) return ExactCcd{};
  return t->exact ? answer_at(t->lo) : answer_at(*t);
}

/// solve(q).hit without rounding the time of contact to doubles (the bisection on bit patterns
/// of answer_at is most of the exact path's work on a hit).
bool solve_hit(const IntQuery& q) {
  return (q.kind == CcdKind::VertexFace ? earliest_vertex_face(q) : earliest_edge_edge(q)).has_value();
}

/// The answer for the only root of f in (lo, hi) (doubles, f(lo) of sign sign_lo, f(hi) of the
/// other): bisection on the bit patterns of doubles with exact signs, then the exact sign at the
/// midpoint of the two adjacent doubles around the root.
ExactCcd answer_between(const Poly& f, double lo, double hi, int sign_lo) {
  std::uint64_t a = bits(lo), b = bits(hi);
  while (b - a > 1) {
    const std::uint64_t mid = a + (b - a) / 2;
    const Q t(from_bits(mid));
    const int s = sign_at(f, t);
    if (s == 0) return answer_at(t);
    (s == sign_lo ? a : b) = mid;
  }
  ExactCcd out;
  out.hit = true;
  out.toi_lo = from_bits(a);
  out.toi_hi = from_bits(b);
  const int s = sign_at(f, Q((Q(out.toi_lo) + Q(out.toi_hi)) / 2));
  out.toi = s == 0 ? ((a & 1) ? out.toi_hi : out.toi_lo) : s == sign_lo ? out.toi_hi : out.toi_lo;
  return out;
}

/// The answer for a hit proven by the filter: t* is the only root of the cubic in (lo, hi); only
/// its rounding is left, done exactly. Falls back to the full solution if the filter's signs are
/// not the exact ones (a filter defect; never observed).
ExactCcd finish_hit(const CcdQuery& q, const CcdFilterVerdict& v) {
  const IntQuery iq = integer_query(q);
  const Poly f = coplanarity_cubic(iq.kind, moving_points(iq));
  if (sign_at(f, Q(v.lo)) != v.sign_lo || sign_at(f, Q(v.hi)) != -v.sign_lo) return solve(iq);
  return answer_between(f, v.lo, v.hi, v.sign_lo);
}

void check_finite(const CcdQuery& q) {
  for (const auto* x : {&q.x0, &q.x1})
    for (const Vec3& p : *x)
      if (!p.allFinite()) throw std::domain_error("exact_ccd: non-finite coordinate");
}

}  // namespace

ExactCcd exact_ccd(const CcdQuery& q) {
  check_finite(q);
  const CcdFilterVerdict v = certified_float_ccd(q);
  switch (v.kind) {
    case CcdFilterVerdict::Kind::Miss:
      return ExactCcd{};
    case CcdFilterVerdict::Kind::Hit:
      if (v.toi) {
        ExactCcd out;
        out.hit = true;
        out.toi = *v.toi;
        out.toi_lo = v.lo;
        out.toi_hi = v.hi;
        return out;
      }
      return finish_hit(q, v);
    case CcdFilterVerdict::Kind::Unproven:
      break;
  }
  return solve(integer_query(q));
}

bool exact_ccd_hit(const CcdQuery& q) {
  check_finite(q);
  // Cheapest certified proofs first: a contact at a vertex (the kind the filter can never prove,
  // exactly at a zero of its conditions; declined at once on generic input), then the filter,
  // then exact arithmetic.
  if (proven_feature_contact(q)) return true;
  const CcdFilterVerdict v = certified_float_ccd(q);
  if (v.kind != CcdFilterVerdict::Kind::Unproven) return v.kind == CcdFilterVerdict::Kind::Hit;
  return solve_hit(integer_query(q));
}

ExactCcd exact_ccd_unfiltered(const CcdQuery& q) { return solve(integer_query(q)); }

ExactCcd exact_ccd(const RationalCcdQuery& q) {
  const RationalPoints v = parse_query(q);
  CcdQuery d;  // the same numbers as doubles, when they all are: filtered
  d.kind = q.kind;
  for (std::size_t s = 0; s < 8; ++s)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::optional<double> x = exact_double(v[s][k]);
      if (!x) return solve(integer_query(q.kind, v));
      (s < 4 ? d.x0[s] : d.x1[s - 4])[static_cast<Eigen::Index>(k)] = *x;
    }
  return exact_ccd(d);
}

bool is_exact_double(const RationalCoord& c) { return exact_double(parse_rational(c)).has_value(); }

double nearest_double(const RationalCoord& c) { return nearest(parse_rational(c)); }

CcdQuery nearest_double_query(const RationalCcdQuery& q) {
  CcdQuery out;
  out.kind = q.kind;
  for (std::size_t i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      out.x0[i][k] = nearest_double(q.x0[i][static_cast<std::size_t>(k)]);
      out.x1[i][k] = nearest_double(q.x1[i][static_cast<std::size_t>(k)]);
    }
  return out;
}

}  // namespace tecido::reference
