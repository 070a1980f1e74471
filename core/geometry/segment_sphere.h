#pragma once
/// A particle's path against a solid sphere (seed section 2.3: "in the case of a sphere it is
/// enough to compare the distance from its centre with its radius", made continuous over the
/// step). Positions are relative to the sphere's centre: r0 at the start of the step, r1 at the
/// end (for a moving sphere, each relative to the centre at that time, so the relative motion is
/// the straight segment r0 -> r1).
#include "core/geometry/types.h"

namespace tecido {

/// True when |r| < radius, evaluated as r.squaredNorm() < radius^2 in floating point: the
/// inside test every sphere decision in the engine uses (a point on the sphere is outside).
inline bool inside_sphere(const Vec3& r, double radius) { return r.squaredNorm() < radius * radius; }

struct SphereEntry {
  bool hit = false;
  double s = 0.0;  ///< fraction along r0 -> r1 at which the path reaches the sphere, in [0, 1]
};

/// Whether the segment r0 -> r1 enters the open ball |r| < radius, and where it first reaches
/// the sphere: the smaller root s of |r0 + s (r1 - r0)|^2 = radius^2 (Vieta's stable form), 0 when
/// r0 is already inside. A path that only grazes the sphere (touches it without entering) or
/// leaves from its surface is no hit. An end point inside (inside_sphere) is always a hit, so a
/// rounding in the roots can never let a step end inside. Method: the quadratic in s.
SphereEntry segment_enters_sphere(const Vec3& r0, const Vec3& r1, double radius);

/// The point of the sphere nearest to r (radius r / |r|; the top, +z, for r = 0), moved out by
/// ulps until inside_sphere is false. Relative to the centre.
Vec3 place_on_sphere(const Vec3& r, double radius);

}  // namespace tecido
