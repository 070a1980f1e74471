#pragma once
/// The JSON result of a run (docs/design.md section 3, `tecido run --json`):
/// {"status":"ok"|"unstable","unstable_at_step":N|null,"time":T,"steps":N,
///  "particles":[{"x":[..],"v":[..]}],"integrator","dt","instability":{...}|null,"contacts":{...}}
/// With obstacles, "obstacles":{contacts, separating, resting_now, resting_corrections,
/// guard_corrections}; with edge_contacts as well, "edge_contacts":{"spring_box":{contacts,
/// separating, moved_out, unresolved, resting_now}, "spring_edge":{contacts, separating,
/// resting_corrections, moved_through, resting_now}} (core/dynamics/spring_box_contacts.h,
/// edge_contacts.h).
/// Numbers are printed with 17 significant digits, so the file round-trips bit for bit.
#include "comparisons/io/json_reader.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

namespace tecido::io {

Json run_result_json(const Simulation& sim);
/// The "self_collision" member of a run with self-collision: {response, checks, contact_checks,
/// share, pairs, max_pairs, pairs_now, gia_regions, gia_failed_checks, gia_unresolved_pairs,
/// unseparated_cut_edges, pushed_particles}.
Json self_collision_json(const SelfCollisionResponder& r);

}  // namespace tecido::io
