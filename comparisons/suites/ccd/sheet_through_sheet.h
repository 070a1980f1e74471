#pragma once
/// A case group for continuous self-collision: a sheet passing through another within one step.
/// Two n x n cloth sheets in one mesh: A flat at z = 0, B above it (turned by 0.3 rad about z,
/// offset, slightly tilted), falling so fast that one step carries it from z = +gap to z = -gap.
/// Neither frame has an intersecting triangle pair, so discrete detection sees nothing; the
/// contacts exist only between the frames.
///
/// What it measures (run_sheet_through_sheet):
///  - the two frames: discrete intersecting pairs (core's detector and the exact brute force) in
///    each, which must be none; the continuous contacts of the exact referee on every pair (the
///    truth), of core (its broad phase and test, each candidate confirmed exactly: must equal
///    the truth), core's candidates against core-brute's (its test on every pair: the broad phase
///    must lose nothing), and core-brute against the truth (no contact missed);
///  - the simulation from the first frame with B's velocity: with discrete detection and no
///    response B ends below A (it passed through, unseen); with continuous detection and the
///    impulse response, the exact referee finds no contact between any two consecutive frames.
/// The `ccd` suite runs it as one case with checks ccd/sheet-through-sheet/... (ccd_suite.cpp); it
/// is self-contained (settings in, counts out) so that the selfcollision suite can take it as a
/// case group of its own.
#include "comparisons/io/json_reader.h"
#include "core/scene/scene.h"

#include <vector>

namespace tecido::suites::ccd {

struct SheetSettings {
  int n = 12;       ///< particles per side of each sheet
  int steps = 8;    ///< simulated steps checked (impulse run)
  double dt = 0.01; ///< [s]
};
inline SheetSettings sheet_settings(bool quick) {
  SheetSettings s;
  if (quick) s.n = 8, s.steps = 4;
  return s;
}

/// The scene (both sheets, B moving down, no gravity) and the step's two frames.
struct SheetScene {
  Scene scene;
  std::vector<Vec3> x0, x1;
  int first_b = 0;  ///< B's first particle
};
SheetScene sheet_through_sheet_scene(const SheetSettings& s);

struct SheetResult {
  long discrete_pairs = 0;     ///< intersecting pairs in either frame, core's detector and exact, summed
  long exact_contacts = 0;     ///< the referee's continuous contacts (vertex-face + edge-edge)
  long core_contacts = 0;      ///< core's confirmed contacts
  long core_missed = 0;        ///< the referee's contacts core does not report
  long core_extra = 0;         ///< core's contacts the referee does not have
  long candidates_differ = 0;  ///< pairs in exactly one of core's candidates and core-brute's
  long brute_missed = 0;       ///< the referee's contacts core-brute does not report
  long discrete_passed = 0;    ///< 1 when the run with discrete detection and no response ended with B below A
  long discrete_run_contacts = 0;  ///< checks of that run where discrete detection found a pair
  long impulse_contacts = 0;   ///< the referee's contacts between consecutive frames of the impulse run, summed
  long impulse_steps = 0;      ///< steps of that run that completed
};

/// Runs the case group (needs the exact referee: reference build).
SheetResult run_sheet_through_sheet(const SheetSettings& s);

io::Json sheet_result_json(const SheetResult& r);
SheetResult sheet_result_from_json(const io::Json& j);

}  // namespace tecido::suites::ccd
