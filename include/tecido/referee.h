#pragma once
/// tecido's exact referee (library tecido::referee): the answers every engine is judged against.
/// Exact: the doubles given are the exact rationals they represent and the answer is what exact
/// arithmetic gives (CGAL 5.5 exact predicates and GMP rationals inside the library; neither
/// reaches this header or your compile flags). Slower than floating-point tests (microseconds a
/// query), thread-safe. Types: tecido/geometry.h. Every function throws std::domain_error when a
/// coordinate is NaN or infinite.
#include <tecido/geometry.h>

#include <vector>

namespace tecido::referee {

/// Whether the closed triangles a and b share at least one point, touching included; a
/// degenerate triangle is the segment or point it spans.
bool tri_tri(const Triangle& a, const Triangle& b);

/// The segment from -> to against the closed rectangle `r`, with right = normal x forward taken
/// exactly and normal, forward not assumed exactly unit or orthogonal (docs/design.md section 1).
/// A segment lying in the plane hits at the first of its points inside. `t` is the exact fraction
/// rounded to the nearest double.
PlaneHit segment_plane(const Rectangle& r, const Vec3& from, const Vec3& to);

/// The exact continuous-collision answer with the bracket of its time of impact.
struct ExactContact {
  bool hit = false;
  double toi = 0.0;     ///< the double nearest the exact first time of contact t* (0 when !hit)
  double toi_lo = 0.0;  ///< toi_lo <= t* <= toi_hi, adjacent doubles (both toi when t* is a double)
  double toi_hi = 0.0;
  bool toi_exact = false;  ///< t* is exactly the double toi
};

/// Whether the closed primitives of `m` touch at some t in [0, 1], and the first such t, decided
/// exactly (roots of the coplanarity cubic isolated exactly; coplanar and degenerate motion
/// included).
ExactContact ccd(const Motion& m);

/// The vertex-face and edge-edge pairs of the mesh F moving linearly from V0 to V1 that touch,
/// decided exactly (core's conservative candidates, tecido::core::continuous_self_collisions,
/// each confirmed by the exact referee): the answer of `tecido selfcollide --mesh V0.obj --to
/// V1.obj`. `threads` >= 1 (the answer does not depend on it). Throws std::domain_error for a
/// non-finite vertex, std::invalid_argument for a bad face, frames of different sizes or threads.
SelfContacts continuous_self_collisions(const std::vector<Vec3>& V0, const std::vector<Vec3>& V1, const Faces& F,
                                        int threads = 1);

}  // namespace tecido::referee
