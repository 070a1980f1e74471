#pragma once
/// The `selfcollision` suite's disagreement file, OUT/selfcollision/disagreements.json: per source,
/// the (engine, frame) entries where an engine's intersecting pairs differ from the truth's (the
/// first Settings::max_entries_per_source, engine order then frame order), each with the true pairs
/// the engine missed and the pairs it reported that are not true (at most
/// Settings::max_pairs_per_list each; the full counts kept), and the positions of the frames they
/// are of, so that a page can draw them:
///   {"truth": NAME, "max_entries_per_source": N, "max_pairs_per_list": M,
///    "sources": [{"source", "entries_found", "triangles": [[a, b, c], ...],
///                 "frames": [{"frame": k, "time": t, "x": [x0, y0, z0, x1, ...]}]}],
///    "entries": [{"id": "<engine>:<source>/<frame>", "engine", "source", "frame", "time",
///                 "missed": [[i, j], ...], "extra": [[i, j], ...], "missed_count", "extra_count"}]}
/// Pairs are triangle indices into the source's "triangles", i < j; positions are the recorded
/// doubles (shortest round-trip text).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/selfcollision/frame_recorder.h"
#include "comparisons/suites/selfcollision/pair_agreement.h"
#include "comparisons/suites/selfcollision/settings.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace tecido::suites::selfcollision {

struct FrameSource;

/// One engine's answer on one frame that differs from the truth's.
struct FrameDisagreement {
  std::string engine;
  int frame = 0;        ///< index of the frame among its source's
  double time = 0.0;    ///< the frame's simulated time [s]
  PairDifference pairs;  ///< at most Settings::max_pairs_per_list of each
  long missed = 0, extra = 0;  ///< the full counts
};

/// What one source keeps for the file.
struct KeptDisagreements {
  long found = 0;  ///< (engine, frame) entries that differ, kept or not
  std::vector<FrameDisagreement> kept;
  std::vector<std::array<int, 3>> triangles;  ///< the mesh; empty when nothing is kept
  std::vector<std::pair<int, Frame>> frames;  ///< (index, frame) of the kept entries' frames

  /// Notes `engine`'s pairs `got` on frame `frame` of `set` against the truth's (both sorted):
  /// counted when they differ, kept within the caps of `s`.
  void note(const Settings& s, const std::string& engine, const FrameSet& set, int frame,
            const std::vector<std::array<int, 2>>& got, const std::vector<std::array<int, 2>>& truth);
};

/// As part of a case result (lossless), and back.
io::Json kept_json(const KeptDisagreements& k);
KeptDisagreements kept_from_json(const io::Json& j);

/// The file's document from every source's kept disagreements (`kept[k]` of `sources[k]`).
io::Json disagreements_json(const std::vector<FrameSource>& sources, const std::vector<KeptDisagreements>& kept,
                            const std::string& truth, const Settings& s);

/// The document as a page draws it (view/view_page.h): the same, each source's triangles as uint32
/// and each frame's "x" as float32, base64 (view/base64.h): a third of the text.
io::Json disagreements_page_doc(const io::Json& doc);

}  // namespace tecido::suites::selfcollision
