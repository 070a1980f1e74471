/// The spring forces of a block of packed springs (packed_springs.cpp) written once over the
/// lane type S of core's SIMD layer (core/simd/): S::kWidth springs at a time, the plain loop's
/// operations in its order lane by lane (force_model.cpp), so every width gives its bits.
// A per-width file (core/simd/target.h): packed_springs.cpp has core/simd/for_each_width.inl
// include it once per width, after Block and pass2. No include guard, no includes, no namespace.

/// Pass 1 for springs k .. k + S::kWidth of the block: the force on each first end into g.
template <class S, bool Damped>
TECIDO_SIMD_INLINE void spring_lanes(const Block& p, int k) {
  using V = typename S::V;
  const V dx = S::load(p.xb + k) - S::load(p.xa + k), dy = S::load(p.yb + k) - S::load(p.ya + k);
  const V dz = S::load(p.zb + k) - S::load(p.za + k);
  const V len = S::sqrt((dx * dx + dy * dy) + dz * dz);
  const V inv_len = S::set1(1.0) / len;
  V mag = S::load(p.ks + k) * (len - S::load(p.ls + k));
  if constexpr (Damped) {
    const V dvx = S::load(p.vxb + k) - S::load(p.vxa + k), dvy = S::load(p.vyb + k) - S::load(p.vya + k);
    const V dvz = S::load(p.vzb + k) - S::load(p.vza + k);
    mag = mag + S::load(p.cs + k) * ((dvx * dx + dvy * dy) + dvz * dz) * inv_len;
  }
  const V c = mag * inv_len;
  // len > 0: false for coincident ends and NaN, whose force is 0 (eq. 10).
  const typename S::K ok = S::lt(S::set1(0.0), len);
  const V zero = S::set1(0.0);
  S::store(p.gx + k, S::select(ok, c * dx, zero));
  S::store(p.gy + k, S::select(ok, c * dy, zero));
  S::store(p.gz + k, S::select(ok, c * dz, zero));
}

/// A whole block: pass 1 in steps of S::kWidth (the last step overlapping the one before it,
/// which rewrites the same values), one spring at a time when the block is narrower than a
/// register, then pass 2.
template <class S, bool Damped>
void block(const Block& block) {
  const Block p = block;  // local copy: no store below can alias it, so its pointers stay in registers
  constexpr int W = S::kWidth;
  if (p.m >= W) {
    for (int k = 0;; k = std::min(k + W, p.m - W)) {
      spring_lanes<S, Damped>(p, k);
      if (k + W == p.m) break;
    }
  } else {
    for (int k = 0; k < p.m; ++k) spring_lanes<::tecido::simd::ScalarLanes, Damped>(p, k);
  }
  pass2(p);
}
