/// The first stages of core's batched continuous collision test (batch/stages.h), written
/// once over the lane type S of core's SIMD layer (core/simd/): staging, boxes, the kinetic
/// program, the cubic's verdict, the root decisions (root.inl) and the loop over blocks.
// A per-width file (core/simd/target.h): batch/stages.cpp has core/simd/for_each_width.inl
// include it once per width, inside that width's namespace and target region, after
// core/simd/lane_math.inl. No include guard, no includes, no namespace.

/// The points of one block of queries in registers: p[time][point][coordinate], one lane per
/// query (points in the order of query.h).
template <class S>
struct Points {
  typename S::V p[2][4][3];
};

#include "core/geometry/ccd/decisions.inl"
#include "core/geometry/ccd/kinetic_program.inl"
#include "core/geometry/ccd/batch/root.inl"

/// The points of one block of queries, lane by lane: p[time][point][coordinate][lane].
template <int W>
struct Staged {
  alignas(64) double p[2][4][3][W];
};

/// Writes the points of queries q[0 .. n) into s (lanes n .. W repeat the last query).
template <int W>
TECIDO_SIMD_INLINE void stage(const double* x0, const double* x1, std::size_t stride, const std::array<int, 4>* q,
                               int n, Staged<W>& s) {
  for (int l = 0; l < W; ++l) {
    const std::array<int, 4>& qq = q[l < n ? l : n - 1];
    for (int pt = 0; pt < 4; ++pt) {
      const std::size_t at = stride * static_cast<std::size_t>(qq[pt]);
      for (int c = 0; c < 3; ++c) {
        s.p[0][pt][c][l] = x0[at + c];
        s.p[1][pt][c][l] = x1[at + c];
      }
    }
  }
}

template <class S>
TECIDO_SIMD_INLINE void load_staged(const Staged<S::kWidth>& s, Points<S>& out) {
  for (int t = 0; t < 2; ++t)
    for (int pt = 0; pt < 4; ++pt)
      for (int c = 0; c < 3; ++c) out.p[t][pt][c] = S::load(s.p[t][pt][c]);
}

/// The primitives' boxes of one block (ccd/pipeline.cpp's box_of: exact minima and maxima).
/// Kind K: 0 vertex-face (first primitive: point 0), 1 edge-edge (points 0 and 1).
template <class S, int K>
TECIDO_SIMD_INLINE void boxes_of(const Points<S>& s, PairBoxes<S>& b) {
  for (int t = 0; t < 2; ++t) {
    for (int c = 0; c < 3; ++c) {
      const auto p0 = s.p[t][0][c], p1 = s.p[t][1][c];
      const auto p2 = s.p[t][2][c], p3 = s.p[t][3][c];
      if (K == 0) {
        b.alo[t][c] = b.ahi[t][c] = p0;
        b.blo[t][c] = vmin<S>(p1, vmin<S>(p2, p3));
        b.bhi[t][c] = vmax<S>(p1, vmax<S>(p2, p3));
      } else {
        b.alo[t][c] = vmin<S>(p0, p1);
        b.ahi[t][c] = vmax<S>(p0, p1);
        b.blo[t][c] = vmin<S>(p2, p3);
        b.bhi[t][c] = vmax<S>(p2, p3);
      }
    }
  }
}

/// Swept boxes disjoint (ccd/pipeline.cpp's box_stages: the union of the two frames' boxes,
/// exact comparisons).
template <class S>
TECIDO_SIMD_INLINE typename S::K swept_disjoint(const PairBoxes<S>& b) {
  typename S::K dis = S::none();
  for (int c = 0; c < 3; ++c) {
    const auto alo = vmin<S>(b.alo[0][c], b.alo[1][c]), ahi = vmax<S>(b.ahi[0][c], b.ahi[1][c]);
    const auto blo = vmin<S>(b.blo[0][c], b.blo[1][c]), bhi = vmax<S>(b.bhi[0][c], b.bhi[1][c]);
    dis = S::kor(dis, S::kor(S::lt(ahi, blo), S::lt(bhi, alo)));
  }
  return dis;
}

/// The cubic's verdict (ccd/system.h's differences, ccd/coplanarity_cubic.cpp's coefficients
/// and cheap bound, ccd/bernstein.h's certified sign), where ccd's scale is 1.
template <class S, int K>
TECIDO_SIMD_INLINE typename S::K cubic_miss(const Points<S>& s, unsigned& unscaled_lanes) {
  using V = typename S::V;
  // Difference vectors X, Y, Z as (minuend, subtrahend) points (ccd/system.cpp's kPairs).
  constexpr int kPairs[2][3][2] = {{{2, 1}, {3, 1}, {0, 1}}, {{1, 0}, {2, 3}, {2, 0}}};
  V3<S> d[2][3];
  V m[3];
  for (int v = 0; v < 3; ++v) {
    m[v] = S::set1(0.0);
    for (int t = 0; t < 2; ++t) {
      V e[3];
      for (int c = 0; c < 3; ++c) {
        e[c] = s.p[t][kPairs[K][v][0]][c] - s.p[t][kPairs[K][v][1]][c];
        m[v] = vmax<S>(m[v], S::abs(e[c]));
      }
      d[t][v] = {e[0], e[1], e[2]};
    }
  }
  V f[4];
  cubic_coefficients<S>(d[0][0], d[1][0], d[0][1], d[1][1], d[0][2], d[1][2], f);
  const V e0 = cubic_cheap_bound<S>(m[0], m[1], m[2]);
  const V lo = vmin<S>(vmin<S>(f[0], f[1]), vmin<S>(f[2], f[3])), hi = vmax<S>(vmax<S>(f[0], f[1]), vmax<S>(f[2], f[3]));
  const V big = vmax<S>(m[0], vmax<S>(m[1], m[2]));
  const auto unscaled = S::kand(S::le(S::set1(0x1p-128), big), S::le(big, S::set1(0x1p125)));
  unscaled_lanes = S::bits(unscaled);
  return S::kand(unscaled, S::kor(S::lt(e0, lo), S::lt(hi, S::set1(0.0) - e0)));
}

/// The first stages' verdicts of one block of queries (lanes valid of them); returns the
/// lanes left open where ccd's scale is 1 (for root_decisions).
template <class S, int K>
TECIDO_SIMD_INLINE unsigned decide_block(const Points<S>& s, int lanes, bool cubic, std::uint8_t* verdict) {
  constexpr int W = S::kWidth;
  PairBoxes<S> b;
  boxes_of<S, K>(s, b);
  unsigned disjoint = S::bits(swept_disjoint<S>(b));
  // The linear program only where some lane needs it (most neighbours overlap at a frame).
  const unsigned open = ~disjoint & ~S::bits(overlap_at_a_frame<S>(b)) & ((1u << W) - 1);
  if (open) disjoint |= open & S::bits(kinetic_program_infeasible<S>(b));
  const unsigned open_lanes = ~disjoint & ((1u << lanes) - 1);
  unsigned unscaled = 0;
  const unsigned miss = cubic && open_lanes ? open_lanes & S::bits(cubic_miss<S, K>(s, unscaled)) : 0u;
  for (int l = 0; l < lanes; ++l)
    verdict[l] = static_cast<std::uint8_t>(((disjoint >> l) & 1u ? kCcdBoxesDisjoint : 0) |
                                           ((miss >> l) & 1u ? kCcdCubicMiss : 0));
  return open_lanes & ~miss & unscaled;
}

/// The points of up to W queries from 64-byte vertex records (x0 x y z, x1 x y z, pad, pad):
/// each point an in-register transpose of the queries' records (the lane type's transpose_8x6).
template <class S>
TECIDO_SIMD_INLINE void load_records(const double* base, const std::array<int, 4>* q, int n, Points<S>& out) {
  if constexpr (S::kTransposes) {
    const int last = n > 1 ? n - 1 : 0;
    for (int pt = 0; pt < 4; ++pt) {
      const double* rows[8];
      for (int l = 0; l < 8; ++l) rows[l] = base + 8 * static_cast<std::size_t>(q[l < n ? l : last][pt]);
      typename S::V col[6];
      S::transpose_8x6(rows, col);
      for (int c = 0; c < 3; ++c) {
        out.p[0][pt][c] = col[c];
        out.p[1][pt][c] = col[3 + c];
      }
    }
  }
}

/// Where the points come from: two arrays with a stride, or (records) both frames interleaved
/// in 64-byte vertex records, which the AVX-512 traits transpose in registers.
struct Source {
  const double *x0, *x1;
  std::size_t stride;
  bool records;
};

/// The points of queries q[0 .. n) (lanes n .. W repeat the last), through memory when the
/// traits do not transpose records.
template <class S>
TECIDO_SIMD_INLINE void load_points(const Source& src, const std::array<int, 4>* q, int n, Points<S>& pts) {
  if constexpr (S::kTransposes) {
    if (src.records) {
      load_records<S>(src.x0, q, n, pts);
      return;
    }
  }
  Staged<S::kWidth> st;
  stage<S::kWidth>(src.x0, src.x1, src.stride, q, n, st);
  load_staged<S>(st, pts);
}

/// Queries the first stages left open, gathered into full blocks for root_decisions (which
/// costs a block whatever the number of lanes it decides).
template <class S>
struct RootQueue {
  std::array<int, 4> q[S::kWidth];
  int at[S::kWidth];
  int n = 0;
};

template <class S, int K>
TECIDO_SIMD_INLINE void run_root(const Source& src, RootQueue<S>& rq, std::uint8_t* verdict) {
  if (rq.n == 0) return;
  Points<S> pts;
  load_points<S>(src, rq.q, rq.n, pts);
  unsigned miss = 0, hit = 0;
  root_decisions<S, K>(pts, (1u << rq.n) - 1, miss, hit);
  for (int l = 0; l < rq.n; ++l)
    verdict[rq.at[l]] |= static_cast<std::uint8_t>(((miss >> l) & 1u ? kCcdRootMiss : 0) | ((hit >> l) & 1u ? kCcdRootHit : 0));
  rq.n = 0;
}

/// The verdicts of queries q[0 .. n) of kind K.
template <class S, int K>
TECIDO_SIMD_INLINE void run_blocks(const double* x0, const double* x1, std::size_t stride, const std::array<int, 4>* q,
                                    int n, bool cubic, std::uint8_t* verdict) {
  constexpr int W = S::kWidth;
  const Source src{x0, x1, stride, S::kTransposes && x1 == x0 + 3 && stride == 8};
  Points<S> pts;
  RootQueue<S> rq;
  // Double-buffered when staged through memory: the next block's points are written while this
  // block's, written one block earlier, are read back as vectors (a wide load of fresh narrow
  // stores would wait for them to leave the store buffer).
  Staged<W> staged[2];
  if (!src.records) stage<W>(x0, x1, stride, q, std::min(W, n), staged[0]);
  for (int k = 0, buf = 0; k < n; k += W, buf ^= 1) {
    const int lanes = std::min(W, n - k);
    if (src.records) {
      load_points<S>(src, q + k, lanes, pts);
    } else {
      if (k + W < n) stage<W>(x0, x1, stride, q + k + W, std::min(W, n - k - W), staged[buf ^ 1]);
      load_staged<S>(staged[buf], pts);
    }
    for (unsigned open = decide_block<S, K>(pts, lanes, cubic, verdict + k); open; open &= open - 1) {
      const int l = __builtin_ctz(open);
      rq.q[rq.n] = q[k + l];
      rq.at[rq.n++] = k + l;
      if (rq.n == W) run_root<S, K>(src, rq, verdict);
    }
  }
  run_root<S, K>(src, rq, verdict);
}

/// The entry point of width S::kWidth (ccd/batch/stages.cpp takes its address).
template <class S, int K>
void stages(const double* x0, const double* x1, std::size_t stride, const std::array<int, 4>* q, int n, bool cubic,
            std::uint8_t* out) {
  run_blocks<S, K>(x0, x1, stride, q, n, cubic, out);
}
