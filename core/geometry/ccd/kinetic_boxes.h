#pragma once
/// A certified rejection of continuous collision queries that sees through common motion:
/// kinetic boxes. At time t every point of a primitive lies in the linear interpolation
/// B(t) = (1 - t) B0 + t B1 of its boxes at t = 0 and t = 1 (for each coordinate,
/// (1 - t) x0 + t x1 >= (1 - t) lo0 + t lo1, and the same above), so two primitives can only
/// touch at a time t where their interpolated boxes overlap on all three axes. Overlap on an
/// axis is two linear inequalities in t (hi_B(t) - lo_A(t) >= 0, hi_A(t) - lo_B(t) >= 0): the
/// test is a one-dimensional linear program over t in [0, 1], six constraints. Swept boxes (the
/// union of B0 and B1) ignore the time at which each primitive is where: two neighbours of a
/// cloth falling together have overlapping swept boxes but disjoint kinetic ones.
///
/// Rounding: each constraint's values at t = 0 and 1 are computed differences d (the true one
/// times 1 + e, |e| <= 2^-53); widening both by m = 2^-50 max |d| (which the rounding of the
/// widening cannot eat) makes each computed constraint at least the true one at every t. A
/// constraint negative at both ends rejects; the others give crossing times -a / (b - a)
/// (b - a without cancellation: a and b of opposite signs), within 3 ulps, widened by 2^-50
/// relative before the lower bounds are compared with the upper ones. So a rejection is
/// certain: no contact.
namespace tecido {

/// Box of a primitive at one instant: lo x, y, z, then hi x, y, z.
using CcdBox = double[6];

/// True when the kinetic boxes of two primitives never overlap for t in [0, 1]: a0, a1 are
/// the first primitive's boxes at t = 0 and t = 1, b0, b1 the second's. Finite input.
bool ccd_kinetic_boxes_disjoint(const CcdBox& a0, const CcdBox& a1, const CcdBox& b0, const CcdBox& b1);

}  // namespace tecido
