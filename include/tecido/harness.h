#pragma once
/// tecido's validation harness as a library (tecido::harness): your engine, written in your own
/// code, validated the way `tecido tritri|ccd|suite --plugin` validates a plug-in, in-process.
///
/// An engine is a tecido_engine table (tecido/plugin.h, the plug-in ABI): fill in the functions
/// it answers (tri_tri, segment_plane, ccd_vertex_face, ccd_edge_edge, create/step/read/destroy),
/// leave the others NULL. The table is checked as a plug-in's is (a name of [A-Za-z0-9_.-], a
/// dynamics engine has all four of create/step/read/destroy, claimed_order in [0, 100]); a bad
/// table throws std::invalid_argument with tecido's one-line message. The table and its name
/// must stay valid during the call that uses it; nothing is kept afterwards.
///
/// Two ways to use it:
///  - query sets: draw the adversarial families of the tritri and ccd suites (the pairs and
///    queries the suites draw for the same seed, with the same ids), run your function on them
///    and compare every answer with the exact referee (check_tri_tri, check_ccd);
///  - suites: run tecido's suites (tritri, ccd, plane, order, stability, drift, ...) with your
///    engines beside tecido's referee and get the report (run_suites).
#include <tecido/geometry.h>
#include <tecido/plugin.h>
#include <tecido/simulation.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tecido::harness {

/// The seed `tecido suite` uses by default.
constexpr std::uint64_t kDefaultSeed = 20141;

/// The installed data directory (tolerances.json, scenes): the package configuration defines
/// TECIDO_DATA_DIR for every target that links tecido::harness; "" without it.
inline std::string default_data_dir() {
#ifdef TECIDO_DATA_DIR
  return TECIDO_DATA_DIR;
#else
  return "";
#endif
}

/// Which cases of the suites' families to draw.
struct CaseOptions {
  std::uint64_t seed = kDefaultSeed;  ///< the suite's --seed: the same seed draws the same cases
  bool quick = true;                  ///< the --quick counts (false: the full suite's counts)
  std::vector<std::string> families;  ///< family names to draw; empty: every family
};

/// A triangle pair of the tritri suite. `id` is "<family>/<k>", as in the suite's reports.
struct TriTriCase {
  std::string id;
  std::string family;
  Triangle a, b;
};

/// A continuous-collision query of the ccd suite ("vertex-face/crossing", ...); `id` is
/// "<family>/<k>", k the query's index in its family.
struct CcdCase {
  std::string id;
  std::string family;
  Motion motion;
};

/// The tritri suite's family names, in report order ("random" first, then the adversarial ones).
std::vector<std::string> tri_tri_families();
/// The ccd suite's family names ("vertex-face/random", ..., "edge-edge/scale").
std::vector<std::string> ccd_families();

/// The families' cases, family by family. Throws std::invalid_argument naming an unknown family.
std::vector<TriTriCase> tri_tri_cases(const CaseOptions& options = {});
std::vector<CcdCase> ccd_cases(const CaseOptions& options = {});

/// One answer that differs from the exact referee's.
struct Disagreement {
  std::string id;
  int answer = 0;       ///< the engine's: 1 hit / intersecting, 0 not, -1 cannot say
  bool truth = false;   ///< the referee's
  double toi = 0.0;     ///< ccd: the engine's time of impact (when answer == 1)
  double truth_toi = 0.0;  ///< ccd: the referee's (when truth)
};

/// Counts of one family.
struct FamilyTally {
  std::string family;
  std::size_t queries = 0;
  std::size_t disagreements = 0;
};

/// An engine's answers on a query set against the exact referee.
struct QueryReport {
  std::string engine;
  std::size_t queries = 0;
  /// Answers that differ from the referee's: misses + false_hits + undecided.
  std::size_t disagreements = 0;
  std::size_t misses = 0;      ///< the referee says contact, the engine says none
  std::size_t false_hits = 0;  ///< the engine says contact, the referee says none
  std::size_t undecided = 0;   ///< the engine answered -1 (cannot say)
  /// ccd: the largest toi - t* over the hits both agree on [fraction of the step]; > 0 means the
  /// engine reported a contact later than it happened (tunnelling risk). 0 for tri_tri.
  double max_late_toi = 0.0;
  std::vector<FamilyTally> families;        ///< in the order the families first appear
  std::vector<Disagreement> first_disagreements;  ///< the first 100, in case order
  /// The report as one JSON object (the fields above).
  std::string json() const;
};

/// `engine.tri_tri` on every case, each answer compared with tecido::referee::tri_tri.
/// Throws std::invalid_argument when the table is malformed or has no tri_tri.
QueryReport check_tri_tri(const tecido_engine& engine, const std::vector<TriTriCase>& cases);

/// `engine.ccd_vertex_face` / `ccd_edge_edge` on every case of the kinds it answers (a case of a
/// kind it leaves NULL is not counted), compared with tecido::referee::ccd: a disagreement is a
/// different hit/miss; times are measured by max_late_toi. Throws std::invalid_argument when the
/// table is malformed or answers no ccd.
QueryReport check_ccd(const tecido_engine& engine, const std::vector<CcdCase>& cases);

/// How to run suites.
struct SuiteOptions {
  bool quick = true;  ///< --quick: smaller counts, same checks
  std::uint64_t seed = kDefaultSeed;
  int threads = 1;  ///< results do not depend on it
  std::string data_dir = default_data_dir();  ///< tolerances.json and scenes/
  /// Where report.json, report.md and the suites' side files go; "" writes nothing (a temporary
  /// directory is used and removed).
  std::string out_dir;
  /// Built-in engines to run beside yours (e.g. {"core"}); the suites' referees always run.
  std::vector<std::string> builtin_engines;
};

/// One check of a suite's report: pass when lo <= value <= hi and value is finite.
struct Check {
  std::string suite;
  std::string name;  ///< "suite/what/detail", as in report.json
  bool has_value = false;
  double value = 0.0;
  double lo = 0.0, hi = 0.0;  ///< +-infinity for an unbounded end
  bool pass = false;
  std::string note;    ///< what the value is
  std::string reason;  ///< why it failed without a value
};

/// What run_suites returns.
struct Report {
  std::vector<Check> checks;
  std::string json;      ///< report.json's text
  std::string markdown;  ///< report.md's text
  std::size_t failed() const;
  /// The checks whose name contains `text` (e.g. an engine's name).
  std::vector<Check> checks_with(const std::string& text) const;
};

/// Runs the named suites (as `tecido suite NAMES --engines ...`) with `engines` registered as
/// outside engines. Throws std::invalid_argument for an unknown suite or engine name, a bad
/// table, a name clashing with a built-in engine; std::runtime_error when a suite fails to run.
Report run_suites(const std::vector<std::string>& suites, const std::vector<tecido_engine>& engines,
                  const SuiteOptions& options = {});

/// A scene file (docs/design.md section 3; data/scenes/ has examples) read as `tecido run` reads
/// it, every value validated, as a tecido::core::Scene to simulate in code (its "steps" is
/// scene.steps()). Throws std::invalid_argument for bad content, std::runtime_error when the file
/// cannot be read, each with the command line's one-line message ("FILE: /json/pointer: problem").
core::Scene load_scene(const std::string& path);

}  // namespace tecido::harness
