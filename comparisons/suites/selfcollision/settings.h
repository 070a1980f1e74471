#pragma once
/// What the `selfcollision` suite runs (its own settings; the tolerance file holds only the lower
/// bounds of precision and recall, /selfcollision/<engine>_min). Printed in the report.
#include <cstddef>

namespace tecido::suites::selfcollision {

struct Settings {
  int frames_per_source = 12;  ///< frames kept from each source (4 with --quick)
  /// Of those, this share at most has a contact by core's detector; the rest has none, so the
  /// comparison is mostly about contacts but also sees frames where nothing touches.
  double contact_share = 0.75;
  double seed_duration = 10.0;        ///< seed-fig21: seconds simulated at most (the experiment's run)
  double seed_frame_interval = 0.05;  ///< seed-fig21: seconds between candidate frames
  int crumple_grid = 24;              ///< crumple: an n x n cloth (16 with --quick)
  long crumple_steps = 1500;          ///< crumple: steps simulated at most (dt 2 ms: 3 s)
  long crumple_every = 25;            ///< crumple: steps between candidate frames
  /// The disagreement file (frame_disagreements.h) keeps, per source, the first this many (engine,
  /// frame) entries where an engine's pairs differ from the truth's, engine order then frame order,
  /// each with its frame's positions ...
  std::size_t max_entries_per_source = 16;
  /// ... and, per entry, at most this many missed and this many extra pairs (the full counts kept).
  std::size_t max_pairs_per_list = 500;
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.frames_per_source = 4;
    s.crumple_grid = 16;
  }
  return s;
}

}  // namespace tecido::suites::selfcollision
