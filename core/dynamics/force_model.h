#pragma once
/// The forces applied before integration (seed section 3.1.1, step 1), each present only when
/// the scene names it: gravity, linear air drag, wind, springs. Forces never touch velocity
/// directly; they are turned into accelerations a_i = F_i / m_i (pinned particles: a = 0).
#include "core/dynamics/packed_springs.h"
#include "core/dynamics/particles.h"
#include "core/dynamics/spring.h"
#include "core/dynamics/wind.h"

#include <optional>
#include <vector>

namespace tecido {

struct ForceModel {
  std::optional<Vec3> gravity;     ///< acceleration [m/s^2]
  std::optional<double> air_drag;  ///< linear drag coefficient c [kg/s]: F = -c v
  std::optional<Wind> wind;
  std::vector<Spring> springs;
};

/// Accelerations at time t of particles at positions x with velocities v:
/// a_i = g + inv_mass_i (wind(t) - c v_i + sum of spring forces on i); a_i = 0 when pinned.
/// `a` is resized to x.size(). Summation order is fixed (springs in array order), so results
/// are bit-identical run to run.
void compute_accelerations(const ForceModel& model, const std::vector<double>& inv_mass, double t,
                           const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& a);

/// The same accelerations with model.springs precompiled into `springs` (built from exactly
/// that list; packed_springs.h): the fast path for repeated evaluations, used by Simulation.
/// Bit-identical to the overload above (same operations, same summation order per particle).
void compute_accelerations(const ForceModel& model, PackedSprings& springs, const std::vector<double>& inv_mass,
                           double t, const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& a);

/// Total spring force on each particle (no gravity, drag or wind), resized to x.size().
/// The plain loop over the list, kept as the obviously-right reference for PackedSprings.
/// Used by tests: internal forces must sum to zero.
void accumulate_spring_forces(const std::vector<Spring>& springs, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v, std::vector<Vec3>& f);

/// Potential energy stored in the springs, 0.5 ks (|x_ij| - l)^2 summed.
double spring_potential_energy(const std::vector<Spring>& springs, const std::vector<Vec3>& x);

}  // namespace tecido
