#include "core/cloth/continuous_self_collision.h"

#include "core/cloth/mesh_topology.h"
#include "core/geometry/ccd/ccd.h"
#include "core/geometry/ccd/batch/stages.h"
#include "core/geometry/ccd/pipeline.h"
#include "core/geometry/outward_float.h"
#include "core/platform/parallel_parts.h"
#include "core/simd/float_lanes.h"

#include <algorithm>
#include <cstdint>


namespace tecido {

namespace {

CcdAnswer default_test(const CcdQuery& q) { return ccd(q); }

bool has_vertex(const std::array<int, 3>& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

bool share_vertex(const MeshEdge& e, const MeshEdge& f) { return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1]; }

/// A pair of nonnegative ids packed so that integer order is the pairs' lexicographic order.
std::uint64_t pair_key(int a, int b) { return static_cast<std::uint64_t>(a) << 32 | static_cast<std::uint32_t>(b); }

void sort_contacts(ContinuousContacts& c) {
  std::sort(c.vertex_face.begin(), c.vertex_face.end());
  std::sort(c.edge_edge.begin(), c.edge_edge.end());
}

/// The unique edges of the mesh, (a, b) with a < b, sorted.
std::vector<MeshEdge> mesh_edges(const std::vector<std::array<int, 3>>& triangles) {
  int nv = 0;
  for (const auto& t : triangles)
    for (int v : t) nv = std::max(nv, v + 1);
  return build_mesh_topology(nv, triangles).edges;
}

/// Pairs queued before the batched first stages run on them.
constexpr int kChunk = 256;

/// Fewest triangle and feature pairs worth a thread of their own.
constexpr std::size_t kMinShare = 4096;

/// Chunks of the pair lists per thread, taken in turn by whichever thread is free.
constexpr int kChunksPerThread = 16;

CcdQuery query_of(CcdKind kind, const std::array<int, 4>& points, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  CcdQuery q;
  q.kind = kind;
  for (int k = 0; k < 4; ++k) {
    q.x0[k] = x0[points[k]];
    q.x1[k] = x1[points[k]];
  }
  return q;
}

}  // namespace

CcdQuery vertex_face_query(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, int v, const std::array<int, 3>& tri) {
  CcdQuery q;
  q.kind = CcdKind::VertexFace;
  q.x0 = {x0[v], x0[tri[0]], x0[tri[1]], x0[tri[2]]};
  q.x1 = {x1[v], x1[tri[0]], x1[tri[1]], x1[tri[2]]};
  return q;
}

CcdQuery edge_edge_query(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const MeshEdge& e, const MeshEdge& f) {
  CcdQuery q;
  q.kind = CcdKind::EdgeEdge;
  q.x0 = {x0[e[0]], x0[e[1]], x0[f[0]], x0[f[1]]};
  q.x1 = {x1[e[0]], x1[e[1]], x1[f[0]], x1[f[1]]};
  return q;
}

ContinuousContacts continuous_self_collision_brute(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                                   const std::vector<std::array<int, 3>>& triangles, CcdTest test) {
  if (!test) test = &default_test;
  ContinuousContacts out;
  std::vector<char> used(x0.size(), 0);
  for (const auto& t : triangles)
    for (int v : t) used[v] = 1;
  for (int v = 0; v < static_cast<int>(x0.size()); ++v) {
    if (!used[v]) continue;
    for (int f = 0; f < static_cast<int>(triangles.size()); ++f)
      if (!has_vertex(triangles[f], v) && test(vertex_face_query(x0, x1, v, triangles[f])).hit) out.vertex_face.push_back({v, f});
  }
  const std::vector<MeshEdge> edges = mesh_edges(triangles);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j)
      if (!share_vertex(edges[i], edges[j]) && test(edge_edge_query(x0, x1, edges[i], edges[j])).hit)
        out.edge_edge.push_back({edges[i], edges[j]});  // edges are sorted: already in order
  sort_contacts(out);
  return out;
}

ContinuousSelfCollisionDetector::ContinuousSelfCollisionDetector(const std::vector<std::array<int, 3>>& triangles,
                                                                 const std::vector<Vec3>& x_build, CcdTest test)
    : tris_(triangles), test_(test ? test : &default_test) {
  int nv = 0;
  for (const auto& t : tris_)
    for (int v : t) nv = std::max(nv, v + 1);
  const MeshTopology topo = build_mesh_topology(nv, tris_);
  edges_ = topo.edges;
  // Owners: the first triangle that has the vertex or edge.
  records_.assign(tris_.size(), TriangleRecord{});
  std::vector<char> vertex_taken(nv, 0), edge_taken(edges_.size(), 0);
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    TriangleRecord& r = records_[t];
    for (int k = 0; k < 3; ++k) {
      const int v = tris_[t][k], e = topo.tri_edges[t][k];  // edge k joins corners k and k + 1
      r.v[k] = v;
      r.edge[k] = e;
      if (!vertex_taken[v]) r.owns_vertex |= 1u << k;
      if (!edge_taken[e]) r.owns_edge |= 1u << k;
      vertex_taken[v] = edge_taken[e] = 1;
    }
  }
  list_neighbour_features(nv);
  bvh_.build(x_build, tris_);
}

void ContinuousSelfCollisionDetector::list_neighbour_features(int vertex_count) {
  // Triangles around each vertex (CSR), then every pair of distinct triangles sharing one.
  std::vector<int> start(vertex_count + 1, 0), around(3 * tris_.size());
  for (const auto& t : tris_)
    for (int v : t) ++start[v + 1];
  for (int v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (int v : tris_[t]) around[fill[v]++] = static_cast<int>(t);
  // In lexicographic order of (i, j), i < j: for each i its later neighbours, sorted and
  // deduplicated in a short list (a handful per triangle; no sort of the whole mesh's pairs).
  std::vector<int> later;
  for (int i = 0; i < static_cast<int>(tris_.size()); ++i) {
    const std::array<int, 3>& t = tris_[static_cast<std::size_t>(i)];
    later.clear();
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) later.push_back(i);  // a corner repeated: i meets itself
    for (int v : t)
      for (int a = start[v]; a < start[v + 1]; ++a)
        if (around[a] > i) later.push_back(around[a]);
    std::sort(later.begin(), later.end());
    later.erase(std::unique(later.begin(), later.end()), later.end());
    for (int j : later) list_feature_pairs(i, j);
  }
}

/// The feature pairs of neighbouring triangles i < j, chosen exactly as test_pair chooses them
/// (each primitive pair comes from the triangle pair of its owners), without the boxes.
void ContinuousSelfCollisionDetector::list_feature_pairs(int i, int j) {
  for (int side = 0; side < 2; ++side) {
    const TriangleRecord& o = records_[side == 0 ? i : j];
    const int f = side == 0 ? j : i;
    const std::array<int, 3>& face = tris_[f];
    for (int k = 0; k < 3; ++k) {
      if (!((o.owns_vertex >> k) & 1u) || has_vertex(face, o.v[k])) continue;
      near_vf_points_.push_back({o.v[k], face[0], face[1], face[2]});
      near_vf_keys_.push_back(pair_key(o.v[k], f));
    }
  }
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      if (!((records_[i].owns_edge >> a) & 1u) || !((records_[j].owns_edge >> b) & 1u)) continue;
      const int ea = records_[i].edge[a], eb = records_[j].edge[b];
      if (share_vertex(edges_[ea], edges_[eb])) continue;
      const MeshEdge& e = edges_[std::min(ea, eb)];
      const MeshEdge& g = edges_[std::max(ea, eb)];
      near_ee_points_.push_back({e[0], e[1], g[0], g[1]});
      near_ee_keys_.push_back(pair_key(std::min(ea, eb), std::max(ea, eb)));
    }
  }
}

bool ContinuousSelfCollisionDetector::run(const CcdQuery& q) const {
  // Core's test: its box stages (and, when they certify, the cubic) were already run here on
  // the same numbers, so go on from the next stage (the same answer).
  return test_ == &default_test ? ccd_after_boxes(q).hit : test_(q).hit;
}

void ContinuousSelfCollisionDetector::sift(Worker& w, CcdKind kind, const std::array<int, 4>* points,
                                          const std::uint64_t* keys, int n, const std::vector<Vec3>& x0,
                                          const std::vector<Vec3>& x1) {
  static_assert(sizeof(VertexFrames) == 8 * sizeof(double), "a vertex's frames are read as 8 doubles");
  const double* base = frames_.empty() ? nullptr : frames_.front().x0;
  // The cubic verdict is core's test's own stage: a custom test gets the box stages only.
  const bool cubic = test_ == &default_test;
  std::vector<std::uint64_t>& found = kind == CcdKind::VertexFace ? w.vf_keys : w.ee_keys;
  w.verdict.resize(kChunk);
  for (int first = 0; first < n; first += kChunk) {
    const int m = std::min(kChunk, n - first);
    ccd_batch_first_stages(kind, base, base + 3, 8, points + first, m, cubic, w.verdict.data(), width_);
    for (int k = 0; k < m; ++k) {
      const std::uint8_t v = w.verdict[k];
      if (v & kCcdBoxesDisjoint) continue;
      ++w.tests;  // the pair passed the box stages: handed to the test
      if (v & (kCcdCubicMiss | kCcdRootMiss)) continue;
      if ((v & kCcdRootHit) || run(query_of(kind, points[first + k], x0, x1))) found.push_back(keys[first + k]);
    }
  }
}

// push, merged and overlap run per feature pair (a few hundred thousand per frame at n = 128):
// forced inline into their callers (left to itself the compiler called them).
TECIDO_SIMD_INLINE void ContinuousSelfCollisionDetector::push(Worker& w, CcdKind kind, const std::array<int, 4>& points, std::uint64_t key,
                                          bool keep, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  // Written whether kept or not, counted only when kept: no branch on the (unpredictable)
  // outcome of the box test that decided `keep`.
  Pending& p = w.pending[kind == CcdKind::VertexFace ? 0 : 1];
  p.points[p.count] = points;
  p.keys[p.count] = key;
  p.count += keep ? 1 : 0;
  if (p.count < kChunk) return;
  sift(w, kind, p.points.data(), p.keys.data(), kChunk, x0, x1);
  p.count = 0;
}

void ContinuousSelfCollisionDetector::flush(Worker& w, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  for (int kind = 0; kind < 2; ++kind) {
    Pending& p = w.pending[kind];
    sift(w, kind == 0 ? CcdKind::VertexFace : CcdKind::EdgeEdge, p.points.data(), p.keys.data(), p.count, x0, x1);
    p.count = 0;
  }
}

// Boxes of four floats (x, y, z, pad), a register's worth of baseline float lanes
// (core/simd/float_lanes.h): min and max choose as minps / maxps at every width.
TECIDO_SIMD_INLINE ContinuousSelfCollisionDetector::FloatBox ContinuousSelfCollisionDetector::merged(const FloatBox& a, const FloatBox& b) {
  using F = simd::BaselineFloatLanes;
  FloatBox m;
  for (int c = 0; c < 4; c += F::kWidth) {
    F::store(m.lo + c, F::min(F::load(a.lo + c), F::load(b.lo + c)));
    F::store(m.hi + c, F::max(F::load(a.hi + c), F::load(b.hi + c)));
  }
  return m;
}

TECIDO_SIMD_INLINE bool ContinuousSelfCollisionDetector::overlap(const FloatBox& a, const FloatBox& b) {
  // Branch-free: the outcome is a coin toss for neighbouring features.
  using F = simd::BaselineFloatLanes;
  unsigned o = 0;
  for (int c = 0; c < 4; c += F::kWidth)
    o |= F::bits(F::kand(F::le(F::load(a.lo + c), F::load(b.hi + c)), F::le(F::load(b.lo + c), F::load(a.hi + c)))) << c;
  return o == 0xFu;
}

void ContinuousSelfCollisionDetector::test_pair(Worker& w, int i, int j, const std::vector<Vec3>& x0,
                                               const std::vector<Vec3>& x1) {
  const TriangleRecord* r[2] = {&records_[i], &records_[j]};
  const int id[2] = {i, j};
  const FloatBox* boxes = boxes_.data();
  FloatBox corner[2][3], tri[2];  // swept boxes of the corners and of the triangles
  for (int side = 0; side < 2; ++side) {
    for (int k = 0; k < 3; ++k) corner[side][k] = boxes[r[side]->v[k]];
    tri[side] = merged(merged(corner[side][0], corner[side][1]), corner[side][2]);
  }
  // Vertices of one triangle against the other face. Every feature's swept box lies in its
  // triangle's: an owned vertex or edge whose box misses the other triangle's misses all of
  // that triangle's features (ccd's stage 2 would reject them all).
  for (int side = 0; side < 2; ++side) {
    const TriangleRecord& o = *r[side];
    const TriangleRecord& f = *r[1 - side];
    for (int k = 0; k < 3; ++k) {
      const int v = o.v[k];
      if (!((o.owns_vertex >> k) & 1u) || v == f.v[0] || v == f.v[1] || v == f.v[2]) continue;
      push(w, CcdKind::VertexFace, {v, f.v[0], f.v[1], f.v[2]}, pair_key(v, id[1 - side]),
           overlap(corner[side][k], tri[1 - side]), x0, x1);
    }
  }
  // Edges of one against edges of the other.
  for (int a = 0; a < 3; ++a) {
    if (!((r[0]->owns_edge >> a) & 1u)) continue;
    const int a0 = r[0]->v[a], a1 = r[0]->v[(a + 1) % 3];
    const FloatBox ea = merged(corner[0][a], corner[0][(a + 1) % 3]);
    if (!overlap(ea, tri[1])) continue;
    for (int b = 0; b < 3; ++b) {
      if (!((r[1]->owns_edge >> b) & 1u)) continue;
      const int b0 = r[1]->v[b], b1 = r[1]->v[(b + 1) % 3];
      if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) continue;
      const FloatBox eb = merged(corner[1][b], corner[1][(b + 1) % 3]);
      // The query exactly as the brute force builds it: the smaller edge id first (ids follow the
      // edges' sorted order) and each edge's endpoints in index order (edges_ holds (a, b) with
      // a < b), not in the triangle's winding. ccd's answer on a near miss within its tolerance
      // can depend on the points' order, so any other order could differ from core-brute
      // (fuzz_selfcollide_continuous: regress_edge_orientation, regress_edge_orientation_missed).
      // The endpoints are ordered here rather than read from edges_: no lookup in the inner loop.
      const bool first = r[0]->edge[a] < r[1]->edge[b];
      const int p0 = std::min(a0, a1), p1 = std::max(a0, a1), q0 = std::min(b0, b1), q1 = std::max(b0, b1);
      const std::array<int, 4> points = first ? std::array<int, 4>{p0, p1, q0, q1} : std::array<int, 4>{q0, q1, p0, p1};
      const std::uint64_t key = first ? pair_key(r[0]->edge[a], r[1]->edge[b]) : pair_key(r[1]->edge[b], r[0]->edge[a]);
      push(w, CcdKind::EdgeEdge, points, key, overlap(ea, eb), x0, x1);
    }
  }
}

void ContinuousSelfCollisionDetector::sift_neighbours(Worker& w, int kind, std::size_t begin, std::size_t end,
                                                     const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  const FloatBox* boxes = boxes_.data();
  const std::vector<std::array<int, 4>>& points = kind == 0 ? near_vf_points_ : near_ee_points_;
  const std::vector<std::uint64_t>& keys = kind == 0 ? near_vf_keys_ : near_ee_keys_;
  for (std::size_t k = begin; k < end; ++k) {
    if (k + 16 < end)
      for (int c = 0; c < 4; ++c) __builtin_prefetch(&boxes[points[k + 16][c]]);
    const std::array<int, 4>& p = points[k];
    if (kind == 0) {  // the vertex against the face
      const FloatBox face = merged(merged(boxes[p[1]], boxes[p[2]]), boxes[p[3]]);
      push(w, CcdKind::VertexFace, p, keys[k], overlap(boxes[p[0]], face), x0, x1);
    } else {  // edge against edge
      push(w, CcdKind::EdgeEdge, p, keys[k], overlap(merged(boxes[p[0]], boxes[p[1]]), merged(boxes[p[2]], boxes[p[3]])),
           x0, x1);
    }
  }
}

void ContinuousSelfCollisionDetector::work(Worker& w, std::atomic<int>& next, int chunks, const std::vector<Vec3>& x0,
                                          const std::vector<Vec3>& x1) {
  w.vf_keys.clear();
  w.ee_keys.clear();
  w.tests = 0;
  for (int chunk; (chunk = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) work_chunk(w, chunk, chunks, x0, x1);
  flush(w, x0, x1);
}

void ContinuousSelfCollisionDetector::work_chunk(Worker& w, int part, int parts, const std::vector<Vec3>& x0,
                                                const std::vector<Vec3>& x1) {
  const auto share = [&](std::size_t n, int k) { return share_begin(n, k, parts); };
  // The pairs' records and their corners' boxes are scattered: fetch them ahead (records 16
  // pairs ahead, the boxes of the corners they name 8 ahead).
  const FloatBox* boxes = boxes_.data();
  const std::size_t np = tri_pairs_.size(), end = share(np, part + 1);
  for (std::size_t k = share(np, part); k < end; ++k) {
    if (k + 16 < end) {
      __builtin_prefetch(&records_[tri_pairs_[k + 16][0]]);
      __builtin_prefetch(&records_[tri_pairs_[k + 16][1]]);
    }
    if (k + 8 < end) {
      for (int side = 0; side < 2; ++side)
        for (int c = 0; c < 3; ++c) __builtin_prefetch(&boxes[records_[tri_pairs_[k + 8][side]].v[c]]);
    }
    test_pair(w, tri_pairs_[k][0], tri_pairs_[k][1], x0, x1);
  }
  for (int kind = 0; kind < 2; ++kind) {
    const std::size_t n = (kind == 0 ? near_vf_points_ : near_ee_points_).size();
    sift_neighbours(w, kind, share(n, part), share(n, part + 1), x0, x1);
  }
}

const ContinuousContacts& ContinuousSelfCollisionDetector::detect(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  tri_pairs_.clear();
  frames_.resize(x0.size());
  boxes_.resize(x0.size());
  FloatBox* boxes = boxes_.data();
  for (std::size_t v = 0; v < x0.size(); ++v) {
    for (int c = 0; c < 3; ++c) {
      frames_[v].x0[c] = x0[v][c];
      frames_[v].x1[c] = x1[v][c];
      boxes[v].lo[c] = float_down(std::min(x0[v][c], x1[v][c]));
      boxes[v].hi[c] = float_up(std::max(x0[v][c], x1[v][c]));
    }
    boxes[v].lo[3] = boxes[v].hi[3] = 0.0f;
  }
  // The tree sees the motion in a frame moving with the mean displacement D: contact is the
  // same when every point at time t is moved by -t D, and the tree's float boxes are rounded
  // outward by far more than the rounding of x1 - D. It leaves out the pairs sharing a vertex
  // (listed once from the topology) and those whose kinetic boxes never meet.
  Vec3 mean = Vec3::Zero();
  for (std::size_t v = 0; v < x0.size(); ++v) mean += x1[v] - x0[v];
  if (!x0.empty()) mean /= static_cast<double>(x0.size());
  moved_.resize(x1.size());
  for (std::size_t v = 0; v < x1.size(); ++v) moved_[v] = x1[v] - mean;
  bvh_.refit(x0, moved_);
  bvh_.moving_pairs(tri_pairs_, threads_);
  run_workers(x0, x1);
  emit_sorted();
  return out_;
}

void ContinuousSelfCollisionDetector::run_workers(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  // A thread is started per share: below a few thousand pairs a share costs less than a start.
  const std::size_t work_items = tri_pairs_.size() + near_vf_points_.size() + near_ee_points_.size();
  const int parts = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads_), 1 + work_items / kMinShare));
  parts_ = parts;
  if (static_cast<int>(workers_.size()) < parts) workers_.resize(static_cast<std::size_t>(parts));
  // Threads take chunks as they free up (contact-dense regions of the list cost many times
  // more than the rest, so equal contiguous shares left one thread waiting for the other).
  std::atomic<int> next{0};
  const int chunks = parts == 1 ? 1 : kChunksPerThread * parts;
  run_parts(parts, [&](int part) { work(workers_[static_cast<std::size_t>(part)], next, chunks, x0, x1); });
  // Each primitive pair is tested by one worker: the merged keys, sorted, are the same pairs
  // whatever the number of parts.
  vf_keys_.clear();
  ee_keys_.clear();
  tests_ = 0;
  for (int part = 0; part < parts; ++part) {
    const Worker& w = workers_[part];
    vf_keys_.insert(vf_keys_.end(), w.vf_keys.begin(), w.vf_keys.end());
    ee_keys_.insert(ee_keys_.end(), w.ee_keys.begin(), w.ee_keys.end());
    tests_ += w.tests;
  }
}

void ContinuousSelfCollisionDetector::emit_sorted() {
  // Sorting the packed keys sorts the pairs: (v, f) lexicographically, and edge pairs by their
  // ids, which follow the edges' lexicographic order.
  std::sort(vf_keys_.begin(), vf_keys_.end());
  std::sort(ee_keys_.begin(), ee_keys_.end());
  out_.vertex_face.resize(vf_keys_.size());
  for (std::size_t k = 0; k < vf_keys_.size(); ++k)
    out_.vertex_face[k] = {static_cast<int>(vf_keys_[k] >> 32), static_cast<int>(vf_keys_[k] & 0xFFFFFFFFu)};
  out_.edge_edge.resize(ee_keys_.size());
  for (std::size_t k = 0; k < ee_keys_.size(); ++k)
    out_.edge_edge[k] = {edges_[ee_keys_[k] >> 32], edges_[ee_keys_[k] & 0xFFFFFFFFu]};
}

ContinuousContacts continuous_self_collision(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                             const std::vector<std::array<int, 3>>& triangles, CcdTest test) {
  ContinuousSelfCollisionDetector d(triangles, x0, test);
  return d.detect(x0, x1);
}

ContinuousContacts filter_contacts(const ContinuousContacts& contacts, const std::vector<Vec3>& x0,
                                   const std::vector<Vec3>& x1, const std::vector<std::array<int, 3>>& triangles,
                                   const std::function<bool(const CcdQuery&)>& keep, int threads) {
  const std::size_t nvf = contacts.vertex_face.size(), n = nvf + contacts.edge_edge.size();
  std::vector<char> kept(n, 0);
  const int parts = std::max(1, threads);
  run_parts(parts, [&](int part) {
    for (std::size_t k = share_begin(n, part, parts); k < share_begin(n, part + 1, parts); ++k) {
      if (k < nvf) {
        const VertexFacePair& vf = contacts.vertex_face[k];
        kept[k] = keep(vertex_face_query(x0, x1, vf[0], triangles[vf[1]]));
      } else {
        const EdgeEdgePair& ee = contacts.edge_edge[k - nvf];
        kept[k] = keep(edge_edge_query(x0, x1, ee[0], ee[1]));
      }
    }
  });
  ContinuousContacts out;
  for (std::size_t k = 0; k < nvf; ++k)
    if (kept[k]) out.vertex_face.push_back(contacts.vertex_face[k]);
  for (std::size_t k = nvf; k < n; ++k)
    if (kept[k]) out.edge_edge.push_back(contacts.edge_edge[k - nvf]);
  return out;
}

}  // namespace tecido
