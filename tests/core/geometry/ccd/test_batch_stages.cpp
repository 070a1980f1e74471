// The batched first stages of core's continuous collision test (core/geometry/ccd/batch/stages.h)
// must decide exactly as ccd's own stages do, at every vector width: swept and kinetic boxes
// (against the pipeline's box computation and ccd_kinetic_boxes_disjoint), the coplanarity
// cubic with its cheap bound (against ccd_coplanarity_cubic on ccd's own system, which is
// unscaled wherever the batch decides), on random, cloth-like, coplanar, near-coplanar and
// degenerate queries at scales 1e-40..1e38; and every query they reject is one ccd misses.
#include "core/geometry/ccd/ccd.h"
#include "core/geometry/ccd/batch/stages.h"
#include "core/geometry/ccd/bernstein.h"
#include "core/geometry/ccd/coplanarity_cubic.h"
#include "core/geometry/ccd/kinetic_boxes.h"
#include "core/geometry/ccd/stats.h"
#include "core/geometry/ccd/system.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace tecido {
namespace {

/// Queries as point indices into two position arrays, as a mesh holds them.
struct Batch {
  std::vector<Vec3> x0, x1;
  std::vector<std::array<int, 4>> points;
  void add(const std::array<Vec3, 4>& a, const std::array<Vec3, 4>& b) {
    std::array<int, 4> idx;
    for (int k = 0; k < 4; ++k) {
      idx[k] = static_cast<int>(x0.size());
      x0.push_back(a[k]);
      x1.push_back(b[k]);
    }
    points.push_back(idx);
  }
  CcdQuery query(CcdKind kind, int k) const {
    CcdQuery q;
    q.kind = kind;
    for (int i = 0; i < 4; ++i) {
      q.x0[i] = x0[points[k][i]];
      q.x1[i] = x1[points[k][i]];
    }
    return q;
  }
};

/// Seven families of queries, then all of them scaled by powers of ten and moved far away.
Batch make_batch(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  auto point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  auto offset = [&](double r) { return Vec3(r * s(rng), r * s(rng), r * s(rng)); };
  Batch base;
  for (int i = 0; i < 800; ++i) {
    std::array<Vec3, 4> a, b;
    const int family = i % 8;
    for (int k = 0; k < 4; ++k) a[k] = point();
    if (family == 0) {  // random-large: independent frames
      for (int k = 0; k < 4; ++k) b[k] = point();
    } else if (family == 1) {  // random-small motion
      for (int k = 0; k < 4; ++k) b[k] = a[k] + offset(0.1);
    } else if (family == 2) {  // cloth-like: a small patch moving together, small relative motion
      const Vec3 c = point(), d = offset(0.05);
      for (int k = 0; k < 4; ++k) {
        a[k] = c + offset(0.01);
        b[k] = a[k] + d + offset(0.002);
      }
    } else if (family == 3) {  // coplanar at all times
      for (int k = 0; k < 4; ++k) {
        a[k].z() = 0.5;
        b[k] = a[k] + offset(0.1);
        b[k].z() = 0.5;
      }
    } else if (family == 4) {  // near-coplanar: the cubic's bound decides at the margin
      for (int k = 0; k < 4; ++k) {
        a[k].z() = 0.5 + 1e-14 * s(rng);
        b[k] = a[k] + offset(0.1);
        b[k].z() = 0.5 + std::ldexp(s(rng), -40 - static_cast<int>(u(rng) * 20));
      }
    } else if (family == 5) {  // degenerate: repeated points, zero-length edges, still points
      const int r = static_cast<int>(u(rng) * 4);
      a[(r + 1) % 4] = a[r];
      for (int k = 0; k < 4; ++k) b[k] = (i % 2 == 0) ? a[k] : a[k] + offset(0.05);
      if (i % 3 == 0) b = a;
    } else if (family == 7) {  // a contact at time ts: the vertex in the face, or the edges crossing
      const double ts = u(rng), cu = 0.8 * u(rng), cv = (0.8 - cu) * u(rng);
      std::array<Vec3, 4> at;
      for (int k = 0; k < 4; ++k) at[k] = point();
      // Vertex-face: point 0 = corner 1 + cu (2 - 1) + cv (3 - 1). Edge-edge: both edges pass
      // through the same point (point 1 chosen so that 0 + cu' (1 - 0) meets 2 + cv' (3 - 2)).
      const Vec3 hitpoint = at[1] + cu * (at[2] - at[1]) + cv * (at[3] - at[1]);
      at[0] = hitpoint;
      for (int k = 0; k < 4; ++k) {
        const Vec3 vel = offset(0.2);
        a[k] = at[k] - ts * vel;
        b[k] = at[k] + (1.0 - ts) * vel;
      }
    } else {  // boxes touching at a frame, exactly (dyadic coordinates)
      for (int k = 0; k < 4; ++k) {
        a[k] = Vec3(std::floor(a[k].x() * 8) / 8, std::floor(a[k].y() * 8) / 8, std::floor(a[k].z() * 8) / 8);
        b[k] = a[k] + Vec3(0.125, 0, 0);
      }
    }
    base.add(a, b);
  }
  Batch all = base;
  for (double scale : {1e-40, 1e-30, 1e-20, 1e-10, 1e10, 1e20, 1e30, 1e38}) {
    for (std::size_t k = 0; k < base.points.size(); ++k) {
      std::array<Vec3, 4> a, b;
      for (int i = 0; i < 4; ++i) {
        a[i] = scale * base.x0[base.points[k][i]];
        b[i] = scale * base.x1[base.points[k][i]];
      }
      all.add(a, b);
    }
  }
  for (std::size_t k = 0; k < base.points.size(); ++k) {  // far from the origin
    std::array<Vec3, 4> a, b;
    for (int i = 0; i < 4; ++i) {
      a[i] = base.x0[base.points[k][i]] + Vec3(1e6, -3e6, 7e5);
      b[i] = base.x1[base.points[k][i]] + Vec3(1e6, -3e6, 7e5);
    }
    all.add(a, b);
  }
  return all;
}

/// ccd's stage 2 on the query: swept boxes (the union of the frames' boxes) disjoint, or
/// kinetic boxes disjoint.
bool boxes_disjoint(const CcdQuery& q) {
  const int split = q.kind == CcdKind::VertexFace ? 1 : 2;
  CcdBox box[2][2];  // [primitive][frame]
  for (int side = 0; side < 2; ++side) {
    for (int frame = 0; frame < 2; ++frame) {
      const auto& x = frame == 0 ? q.x0 : q.x1;
      const int first = side == 0 ? 0 : split, last = side == 0 ? split : 4;
      for (int c = 0; c < 3; ++c) {
        box[side][frame][c] = box[side][frame][c + 3] = x[first][c];
        for (int k = first + 1; k < last; ++k) {
          box[side][frame][c] = std::min(box[side][frame][c], x[k][c]);
          box[side][frame][c + 3] = std::max(box[side][frame][c + 3], x[k][c]);
        }
      }
    }
  }
  for (int c = 0; c < 3; ++c) {
    const double alo = std::min(box[0][0][c], box[0][1][c]), ahi = std::max(box[0][0][c + 3], box[0][1][c + 3]);
    const double blo = std::min(box[1][0][c], box[1][1][c]), bhi = std::max(box[1][0][c + 3], box[1][1][c + 3]);
    if (ahi < blo || bhi < alo) return true;
  }
  return ccd_kinetic_boxes_disjoint(box[0][0], box[0][1], box[1][0], box[1][1]);
}

/// ccd's cubic stage where the batch decides (largest component of X, Y, Z in
/// [2^-128, 2^125]), with the cheap bound ccd keeps when it certifies. Checks on the way that
/// ccd's system is unscaled there (its differences are the raw ones).
bool cubic_rejects_cheaply(const CcdQuery& q) {
  CcdSystem s;
  if (prepare_ccd_system(q, s) != CcdPrepared::Ok) return false;
  const int pairs[2][3][2] = {{{2, 1}, {3, 1}, {0, 1}}, {{1, 0}, {2, 3}, {2, 0}}};
  const int kind = q.kind == CcdKind::VertexFace ? 0 : 1;
  double m[3] = {0.0, 0.0, 0.0};
  bool raw = true;
  for (int v = 0; v < 3; ++v) {
    for (int t = 0; t < 2; ++t) {
      const auto& x = t == 0 ? q.x0 : q.x1;
      for (int c = 0; c < 3; ++c) {
        const double d = x[pairs[kind][v][0]][c] - x[pairs[kind][v][1]][c];
        m[v] = std::max(m[v], std::fabs(d));
        raw = raw && d == s.d[t][v][c];
      }
    }
  }
  const double big = std::max(m[0], std::max(m[1], m[2]));
  if (!(big >= 0x1p-128 && big <= 0x1p125)) return false;
  EXPECT_TRUE(raw) << "ccd rescaled a query the batch decides";
  double f[4];
  CcdErrorBound err;
  ccd_coplanarity_cubic(s, f, err);
  const double cheap = 0x1p-49 * (6.0 * (1.0 + 0x1p-50)) * (m[0] * m[1] * m[2]) + 0x1p-900;
  return ccd_certified_sign(f, 4, 1, cheap) != 0;
}

/// The verdict bits of the first stages (the root's are checked separately).
constexpr std::uint8_t kFirstStages = kCcdBoxesDisjoint | kCcdCubicMiss;

std::vector<int> widths() {
  std::vector<int> w;
  for (int k : {1, 2, 4, 8})
    if (ccd_batch_width_available(k)) w.push_back(k);
  return w;
}

TEST(CcdBatchStages, DecidesAsCcdsOwnStagesAtEveryWidth) {
  for (CcdKind kind : {CcdKind::VertexFace, CcdKind::EdgeEdge}) {
    const Batch b = make_batch(kind == CcdKind::VertexFace ? 11 : 12);
    const int n = static_cast<int>(b.points.size());
    std::vector<std::uint8_t> expected(n);
    int box_misses = 0, cubic_misses = 0;
    for (int k = 0; k < n; ++k) {
      const CcdQuery q = b.query(kind, k);
      const bool boxes = boxes_disjoint(q), cubic = cubic_rejects_cheaply(q);
      // The cubic's verdict is given only where the boxes leave the query open.
      expected[k] = static_cast<std::uint8_t>(boxes ? kCcdBoxesDisjoint : (cubic ? kCcdCubicMiss : 0));
      box_misses += boxes;
      cubic_misses += cubic && !boxes;
      if (boxes || cubic) {
        EXPECT_FALSE(ccd(q).hit) << ccd_kind_name(kind) << " query " << k;
      }
    }
    EXPECT_GT(box_misses, n / 10);  // the families exercise both stages
    EXPECT_GT(cubic_misses, n / 20);
    const double* x0 = b.x0.front().data();
    const double* x1 = b.x1.front().data();
    for (int w : widths()) {
      // Odd counts and offsets: partial blocks.
      for (int first : {0, 3}) {
        std::vector<std::uint8_t> got(n, 0xFF);
        ccd_batch_first_stages(kind, x0, x1, 3, b.points.data() + first, n - first, true, got.data(), w);
        for (int k = first; k < n; ++k)
          ASSERT_EQ(got[k - first] & kFirstStages, expected[k]) << ccd_kind_name(kind) << " width " << w << " query " << k;
      }
      // Both frames interleaved in 64-byte records (x0, x1, two pads): the layout the
      // continuous self-collision detector passes, which the AVX-512 path transposes.
      std::vector<double> records(8 * b.x0.size(), -1.0);
      for (std::size_t v = 0; v < b.x0.size(); ++v)
        for (int c = 0; c < 3; ++c) {
          records[8 * v + c] = b.x0[v][c];
          records[8 * v + 3 + c] = b.x1[v][c];
        }
      for (int first : {0, 5}) {
        std::vector<std::uint8_t> got(n, 0xFF);
        ccd_batch_first_stages(kind, records.data(), records.data() + 3, 8, b.points.data() + first, n - first, true,
                               got.data(), w);
        for (int k = first; k < n; ++k)
          ASSERT_EQ(got[k - first] & kFirstStages, expected[k]) << "records, width " << w << " query " << k;
      }
      std::vector<std::uint8_t> boxes_only(n);
      ccd_batch_first_stages(kind, x0, x1, 3, b.points.data(), n, false, boxes_only.data(), w);
      for (int k = 0; k < n; ++k) ASSERT_EQ(boxes_only[k], expected[k] & kCcdBoxesDisjoint) << "width " << w;
    }
  }
}

TEST(CcdBatchStages, RootDecisionsAreCcdsAndTheSameAtEveryWidth) {
  // The root of the time search replayed (batch/root.inl): a lane it decides must be one ccd
  // answers the same way, within its first node (or by the cubic's permanent bound) and
  // without the inclusion search; every width decides the same lanes the same way.
  for (CcdKind kind : {CcdKind::VertexFace, CcdKind::EdgeEdge}) {
    const Batch b = make_batch(kind == CcdKind::VertexFace ? 21 : 22);
    const int n = static_cast<int>(b.points.size());
    const double* x0 = b.x0.front().data();
    const double* x1 = b.x1.front().data();
    std::vector<std::uint8_t> reference;
    for (int w : widths()) {
      std::vector<std::uint8_t> got(n);
      ccd_batch_first_stages(kind, x0, x1, 3, b.points.data(), n, true, got.data(), w);
      if (reference.empty()) reference = got;
      ASSERT_EQ(got, reference) << "width " << w;
    }
    int misses = 0, hits = 0;
    for (int k = 0; k < n; ++k) {
      const std::uint8_t v = reference[k];
      if (!(v & (kCcdRootMiss | kCcdRootHit))) continue;
      EXPECT_FALSE(v & kFirstStages);
      ccd_stats() = CcdStats{};
      const CcdAnswer a = ccd(b.query(kind, k));
      const CcdStats st = ccd_stats();
      EXPECT_EQ(a.hit, (v & kCcdRootHit) != 0) << ccd_kind_name(kind) << " query " << k;
      EXPECT_TRUE(st.time_search_nodes == 1 || st.cubic_rejections == 1) << "query " << k;
      EXPECT_EQ(st.inclusion_calls, 0u) << "query " << k;
      misses += (v & kCcdRootMiss) != 0;
      hits += (v & kCcdRootHit) != 0;
    }
    EXPECT_GT(misses, 50) << ccd_kind_name(kind);
    EXPECT_GT(hits, 50) << ccd_kind_name(kind);
  }
}

}  // namespace
}  // namespace tecido
