#pragma once
/// Suite `obstacles` (issue: obstacles and moving bodies): particles and a cloth against spheres
/// and boxes, static and moving, in core: analytic cases against closed forms (a drop on a sphere,
/// a slide with the seed's friction, resting, fast particles and huge steps: no step ends inside);
/// the seed's cloth-on-a-block artefact (figs 10-13) as a table of springs through the block per
/// frame at 121 and 484 particles, edge contacts off and on; and, in the reference build, Bullet's
/// classic soft body on the same scenes and FCL's continuous test as a second opinion on contact
/// times.
///
/// Layout: settings.h (what runs), theory.* (closed forms), box_interior.* (the artefact's
/// measurement), analytic_cases.*, block_scene.*, block_case.*, bullet_cases.*, fcl_cases.* (the cases),
/// cases.* (the table), check_plan.* and bullet_checks.* (checks declared before anything runs),
/// obstacles_report.* and block_report.cpp (report); this file builds the sweep and assembles.
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

namespace tecido::suites {

/// The suite as a sweep: one case per entry of obstacles::cases().
Sweep obstacles_sweep(const SuiteContext& ctx);
SuiteResult run_obstacles_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
