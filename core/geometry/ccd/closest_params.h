#pragma once
/// The parameters (u, v) of the closest points of a continuous collision query's primitives at
/// one instant: where |F(t, u, v)| = |Z - u X - v Y| is smallest over the domain (ccd/system.h).
/// Floating point, approximate: the inclusion search (ccd/inclusion.h) only uses them to
/// choose a separating direction and a point to evaluate with a rigorous error bound, so an
/// inexact minimiser costs efficiency, never correctness.
namespace tecido {

/// Vertex-face: the closest point of the triangle a + u X + v Y (u, v >= 0, u + v <= 1) to
/// a + Z, by Voronoi regions (Ericson 2005, "Real-Time Collision Detection", 5.1.5). Returns
/// (u, v) in the domain: u, v in [0, 1] and u + v <= 1 up to one rounding.
void ccd_closest_on_triangle(const double x[3], const double y[3], const double z[3], double& u, double& v);

/// Edge-edge: the closest points of a0 + u X and b0 - v Y (u, v in [0, 1]) with Z = b0 - a0,
/// i.e. the minimiser of |Z - u X - v Y| (Ericson 2005, 5.1.9, degenerate segments included).
void ccd_closest_on_segments(const double x[3], const double y[3], const double z[3], double& u, double& v);

}  // namespace tecido
