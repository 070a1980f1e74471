#pragma once
/// A simple velocity-level response to continuous contacts (self-collision response "impulse"):
/// an inelastic impulse at the time of impact, after Bridson, Fedkiw and Anderson 2002
/// ("Robust treatment of collisions, contact and friction for cloth animation", section 7.1).
///
/// For one contact (vertex-face or edge-edge) between positions x0 and x1 of a check interval
/// of length h (the particles' average velocities are (x1 - x0) / h):
///  1. its time of impact t by core's continuous test (core/geometry/ccd/ccd.h: never after the
///     true one), and the primitives' positions at t;
///  2. the contact's barycentric weights w (vertex-face: 1 on the vertex, -u, -v, -w on the
///     corners, (u, v, w) the vertex's projection onto the triangle, clamped into it; edge-edge:
///     (1 - s), s on one edge and -(1 - r), -r on the other, s and r the closest points' clamped
///     parameters) and normal n (the triangle's normal, or the edges' cross product), oriented so
///     that the weighted separation d0 = n . sum w_i x0_i at the start is > 0: the side to keep
///     (a contact already touching at the start, d0 = 0, has no side and is left alone).
///     Degenerate geometry (zero-area triangle, parallel or zero-length edges) takes n along the
///     weighted separation at the start, else against the relative motion;
///  3. the relative normal velocity vn = n . sum w_i vbar_i. When it is below -(1 - kKeptGap) d0 / h,
///     the approach would close more than (1 - kKeptGap) of the starting gap along n; the impulse
///     raises vn to exactly that rate (inelastic: no bounce), distributed by the weights and the
///     inverse masses: dv_i = w_i inv_mass_i I n, I = (target - vn) / sum w_i^2 inv_mass_i
///     (the exact solution for one contact; pinned particles do not move). Each changed
///     particle's end position moves with its velocity: x1_i += h dv_i, v_i += dv_i.
/// Contacts are treated one after the other in their sorted order (Gauss-Seidel), so the result
/// is deterministic; the caller detects again and repeats (SelfCollisionResponder), since one
/// impulse can create another contact. Bridson et al. fall back to rigid impact zones when
/// iterations do not converge; this simple response does not (the caller counts what remains).
#include "core/cloth/continuous_self_collision.h"

#include <array>
#include <vector>

namespace tecido {

/// Share of the starting gap along the contact normal an impulse keeps at the end of the interval.
constexpr double kKeptGap = 0.5;

/// Applies the impulse of every contact of `c` in order (see the file comment); returns how many
/// impulses changed a velocity. x1 and v are updated in place; x0 is the interval's start.
int apply_contact_impulses(const ContinuousContacts& c, const std::vector<std::array<int, 3>>& triangles,
                           const std::vector<Vec3>& x0, std::vector<Vec3>& x1, std::vector<Vec3>& v,
                           const std::vector<double>& inv_mass, double h);

}  // namespace tecido
