#pragma once
/// One step of an n x n cloth folding onto itself: the mesh of the continuous self-collision
/// benchmarks (bench/bench_continuous_self_collision.cpp) and of the `bench` suite's timing of the
/// whole `tecido selfcollide` process; scripts/fold_frames.py writes the same frames from Python.
///
/// A square of side 1 m, (n - 1)^2 quads cut into two triangles each (core/scene/cloth_builder.h's
/// numbering), folded over itself along x = 0.5 (a half-turn bend of radius H / 2, the flap's flat
/// part at height H) with a ripple of amplitude 0.03 m (sin(9u + 1) sin 7v) on both layers, so the
/// layers cross along curves. Fast step: the fold closes from H = 0.04 m to 0.02 m while the whole
/// cloth falls 1 cm (1.2 m/s and 0.6 m/s over a 60 Hz step; the layers pass through each other
/// over a wide band). Gentle step: from H = 0.0225 m, falling 2 mm.
#include "core/geometry/types.h"

#include <array>
#include <string>
#include <vector>

namespace tecido::suites::bench {

struct FoldingStep {
  std::vector<Vec3> rest, x0, x1;  ///< flat rest shape, start and end frames
  std::vector<std::array<int, 3>> triangles;
};

/// The step of an n x n cloth (n >= 2), fast or gentle. Deterministic.
FoldingStep folding_cloth_step(int n, bool gentle = false);

/// The two frames' OBJ files.
struct FoldingFiles {
  std::string start, end;
};

/// Writes the step's frames to `dir`/fold_<n>_t0.obj and fold_<n>_t1.obj (17 significant digits:
/// the doubles round-trip), atomically; throws io::OutputError.
FoldingFiles write_folding_step(const FoldingStep& step, int n, const std::string& dir);

}  // namespace tecido::suites::bench
