#pragma once
/// The seed's self-contact experiment (section 3.1.3, fig. 21, tables 1-3): one cloth scene
/// run 72 times, cloth elasticity {0.9, 0.5} x step {0.02, 0.01, 0.005} s x wind {0.09, 0.1,
/// 0.11} N x response {none, edge mode 1, 2, 3}, 10 s of simulated time each; the figure is the
/// share of frames (steps) after which a self-intersection was detected.
///
/// Each run takes the base scene (data/scenes/seed_fig21_self_contact.json) and changes only:
///  - dt, and steps = round(T / dt) (T = 10 s, 2 s with --quick);
///  - the wind's magnitude (its direction and swirl stay as written);
///  - the cloth's elasticity e, read one of two ways (`elasticity_as`):
///      "stiffness"   (default) e scales the cloth's spring stiffness: stiffness_b and
///                    stiffness_a of the file are those of e = 1 and are multiplied by e
///                    (the seed calls ks "o quociente de elasticidade do tecido", 3.1.2);
///      "restitution" e is the particles' restitution quotient k (cloth.elasticity), the
///                    springs as written; k acts only in plane contacts, so in this plane-free
///                    scene the two elasticity rows then differ by nothing;
///  - self_collision.response: none, edge1, edge2, edge3 (`every` as written; the strength as
///    written unless opt.strength overrides it).
/// A frame is one step; detection runs after every step ("every" must be 1 in the scene), so a
/// run has T/dt frames (500, 1000, 2000; the seed's tables imply 501, 1001 and 2000).
/// Runs are independent and each writes only its own slot, so the results are bit-identical
/// whatever the number of threads.
#include "comparisons/io/json_reader.h"

#include <string>
#include <vector>

namespace tecido::suites {

struct SelfContactRun {
  int index = 0;
  double elasticity = 0.0;
  double dt = 0.0;
  double wind = 0.0;
  int mode = 0;  ///< 0 = no response, 1..3 = the seed's edge modes
};

struct SelfContactResult {
  SelfContactRun run;
  long long frames = 0;          ///< frames (steps) checked
  long long contact_frames = 0;  ///< ... with at least one intersecting triangle pair
  double share = 0.0;            ///< contact_frames / frames
  std::string status = "ok";     ///< "ok" or "unstable"
  long long unstable_at_step = -1;
  long long pairs = 0;           ///< intersecting pairs summed over frames
  long long max_pairs = 0;
};

struct SelfContactOptions {
  std::string scene_path;       ///< base scene
  std::string seed_table_path;  ///< the seed's tables 1-3 (data/seed_tables/self_contact_share.json)
  double simulated_time = 10.0; ///< [s] per run (2 with --quick)
  bool quick = false;
  int threads = 1;
  std::vector<int> runs;        ///< run indices to do (empty = all 72)
  std::string elasticity_as = "stiffness";
  double strength = -1.0;       ///< response force [N]; < 0 = the scene's self_collision.strength
  int shard_index = 0;          ///< --shard i/n: only the runs whose index % n == i
  int shard_count = 1;
  bool progress = false;        ///< a progress bar on stderr (only when it is a terminal)
};

/// The 72 runs in their fixed order: index = ((wind * 3 + step) * 2 + elasticity) * 4 + mode
/// over wind {0.09, 0.1, 0.11}, step {0.02, 0.01, 0.005}, elasticity {0.9, 0.5} (the seed's
/// row order), mode {none, 1, 2, 3}.
std::vector<SelfContactRun> self_contact_runs();

/// The scene of one run: the base scene document patched as described above.
io::Json self_contact_scene(const io::Json& base, const SelfContactRun& run, const SelfContactOptions& opt,
                            const std::string& base_file);

/// Runs one simulation and counts its frames with self-contact.
SelfContactResult run_self_contact(const io::Json& base, const SelfContactRun& run, const SelfContactOptions& opt);

/// The run indices chosen by opt.runs (all 72 when empty), in the order given, before
/// sharding; throws io::UsageError on an index outside 0..71.
std::vector<int> self_contact_selection(const SelfContactOptions& opt);

/// Runs the chosen runs (of them, only this shard's: index % shard_count == shard_index) on
/// opt.threads threads; results in the selection's order.
std::vector<SelfContactResult> run_self_contact_experiment(const SelfContactOptions& opt);

/// experiment.json: {"experiment":"self-contact", "scene", "simulated_time", "quick",
/// "elasticity_as", "strength", "runs":[{"index","elasticity","dt","wind","mode","frames","contact_frames",
/// "share","status","unstable_at_step","pairs","max_pairs"}]}. No wall time, no thread count:
/// the file is bit-identical across thread counts.
std::string self_contact_json(const std::vector<SelfContactResult>& results, const SelfContactOptions& opt);

/// A shard's experiment.json (--shard i/n): {"shard":[i,n], "selection":[the unsharded run
/// indices, in order], "seed_table", then the fields of self_contact_json with only this
/// shard's runs}. `tecido merge` (comparisons/suites/merge.h) rebuilds the unsharded files.
std::string self_contact_shard_json(const std::vector<SelfContactResult>& results, const SelfContactOptions& opt);

/// experiment.md: tables 1-3's layout with our share beside the seed's, and the verdict on the
/// seed's conclusions (needs the seed's tables document).
std::string self_contact_markdown(const std::vector<SelfContactResult>& results, const io::Json& seed_tables,
                                  const SelfContactOptions& opt);

}  // namespace tecido::suites
