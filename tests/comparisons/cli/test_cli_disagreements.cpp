// Disagreements that explain themselves, as a user meets them: a suite run with an engine that
// disagrees with the referee names, per engine, its misses and false hits, the first ids and the
// file holding them all, and a replay command carrying the engine's door; that command, run as
// printed, counts exactly the suite's misses and false hits for that engine (ccd with a naive
// continuous test through the JSON-lines door, and core; the example plug-in given by a relative
// path, replayed by its absolute one; tritri with the seed's MT test; plane's engines). Each
// entry of the file names its engine, the engine's answer and the referee's. And a time of
// impact reported late fails the late-toi check of an outside engine, while an engine on time
// passes it.
#include "comparisons/io/ccd_queries.h"
#include "reference/exact_ccd.h"
#include "tests/support/cli_runner.h"
#include "tests/support/outside_fixtures.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

namespace tecido {
namespace {

using nlohmann::json;
using testing::quoted;
using testing::run_cli;

/// The replay command the suite printed on stderr for `engine` (without the leading "tecido "),
/// or "" when it printed none.
std::string printed_replay(const std::string& err, const std::string& suite, const std::string& engine) {
  const std::size_t line = err.find(suite + ": " + engine + ": ");
  if (line == std::string::npos) return "";
  const std::size_t end = err.find('\n', line);
  const std::string text = err.substr(line, end - line);
  const std::string key = "replay: tecido ";
  const std::size_t at = text.find(key);
  return at == std::string::npos ? "" : text.substr(at + key.size());
}

/// Misses and false hits of one engine, summed over a suite's families.
struct EngineCounts {
  long misses = 0, false_hits = 0;
};

/// The ccd suite's counts of `engine` over every family of report.json's data.
EngineCounts ccd_counts(const json& data, const std::string& engine) {
  EngineCounts c;
  for (const auto& [family, f] : data.items()) {
    if (!f["engines"].contains(engine)) continue;
    c.misses += f["engines"][engine]["fn"].get<long>();
    c.false_hits += f["engines"][engine]["fp"].get<long>();
  }
  return c;
}

const json* check_in(const json& report, const std::string& name) {
  for (const auto& s : report["suites"])
    for (const auto& c : s["checks"])
      if (c["name"] == name) return &c;
  return nullptr;
}

/// Runs the replay the suite printed for `engine` and checks that it counts the suite's numbers;
/// an engine without disagreements has no replay line and no counts.
void expect_replay_reproduces(const std::string& err, const std::string& suite, const std::string& engine,
                              const EngineCounts& c, const std::string& unit) {
  const std::string replay = printed_replay(err, suite, engine);
  if (c.misses + c.false_hits == 0) {
    EXPECT_EQ(err.find(suite + ": " + engine + ": "), std::string::npos) << err;
    return;
  }
  ASSERT_FALSE(replay.empty()) << engine << ":\n" << err;
  EXPECT_NE(replay.find("--engines " + engine + " --of-engine " + engine), std::string::npos) << replay;
  const auto r = run_cli(replay);
  ASSERT_EQ(r.code, 0) << replay << "\n" << r.err;
  const std::string want = "tecido " + suite + ": " + engine + ": " + std::to_string(c.false_hits) +
                           " false positives, " + std::to_string(c.misses) + " false negatives of " +
                           std::to_string(c.misses + c.false_hits) + " " + unit;
  EXPECT_NE(r.err.find(want), std::string::npos) << "want: " << want << "\ngot: " << r.err;
}

TEST(CliDisagreements, ACcdReplayOfOneEngineReproducesTheSuitesCounts) {
  const auto dir = testing::temp_dir("disagree-ccd");
  const std::string door = " --engine-cmd " + quoted("naive=" + testing::misbehaving_engine("ccd-sampled"));
  const auto r = run_cli("suite ccd --quick --threads 2" + door + " --engines core,naive --out " + quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err;  // the naive test misses contacts on random motion
  const json report = json::parse(testing::slurp(dir / "report.json"));
  const json& data = report["suites"][0]["data"];
  const EngineCounts naive = ccd_counts(data, "naive"), core = ccd_counts(data, "core");
  ASSERT_GT(naive.misses, 0);
  ASSERT_GT(naive.false_hits, 0);
  EXPECT_EQ(core.misses, 0);

  // stderr names the naive engine's counts, its first ids and the file.
  const std::string file = std::filesystem::absolute(dir / "ccd" / "disagreements.json").lexically_normal().string();
  EXPECT_NE(r.err.find("ccd: naive: " + std::to_string(naive.misses) + " misses (false negatives), " +
                       std::to_string(naive.false_hits) + " false hits (false positives); first: naive:"),
            std::string::npos) << r.err;
  EXPECT_NE(r.err.find("all in " + file), std::string::npos) << r.err;
  // The report's replay carries the door as given.
  const std::string md = testing::slurp(dir / "report.md");
  EXPECT_NE(md.find("--engines naive --of-engine naive --engine-cmd 'naive=" + testing::misbehaving_engine("ccd-sampled") + "'"),
            std::string::npos);

  // Each entry names its engine, the engine's answer and the referee's, worked out again here.
  const json doc = json::parse(testing::slurp(file));
  const auto entries = io::load_ccd_queries_json(file);
  ASSERT_EQ(entries.size(), static_cast<std::size_t>(naive.misses + naive.false_hits + core.false_hits));
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const json& e = doc["queries"][k];
    const std::string engine = e["engine"];
    EXPECT_EQ(entries[k].id.rfind(engine + ":", 0), 0u) << entries[k].id;
    const reference::ExactCcd exact = reference::exact_ccd(entries[k].query);
    EXPECT_EQ(e["referee"]["hit"], exact.hit) << entries[k].id;
    EXPECT_EQ(e["truth"], exact.hit) << entries[k].id;
    if (exact.hit) EXPECT_EQ(e["referee"]["toi"].get<double>(), exact.toi) << entries[k].id;
    else EXPECT_TRUE(e["referee"]["toi"].is_null()) << entries[k].id;
    EXPECT_NE(e["answer"]["hit"], e["referee"]["hit"]) << entries[k].id;
    if (engine == "naive" && e["answer"]["hit"].get<bool>()) {
      const double t = e["answer"]["toi"];  // the naive test looks at t = 0, 0.5, 1 only
      EXPECT_TRUE(t == 0.0 || t == 0.5 || t == 1.0) << t;
    }
  }

  expect_replay_reproduces(r.err, "ccd", "naive", naive, "queries");
  expect_replay_reproduces(r.err, "ccd", "core", core, "queries");
  // --of-engine takes an engine's entries by the "<engine>:" of their ids: another name takes none.
  const auto none = run_cli("ccd --queries " + quoted(file) + " --engines core --of-engine naiv --json");
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_EQ(json::parse(none.out)["results"].size(), 0u);
  EXPECT_NE(none.err.find("tecido ccd: core: 0 false positives, 0 false negatives of 0 queries"), std::string::npos)
      << none.err;
  std::filesystem::remove_all(dir);
}

TEST(CliDisagreements, APluginGivenByARelativePathIsReplayedByItsAbsolutePath) {
  const auto dir = testing::temp_dir("disagree-plugin");
  const std::string relative = std::filesystem::relative(testing::kExamplePlugin).string();
  ASSERT_NE(relative.front(), '/');
  const auto r = run_cli("suite ccd --quick --threads 2 --plugin " + quoted(relative) + " --engines sampled-ccd --out " +
                         quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err;  // the sampled test misses contacts
  const std::string replay = printed_replay(r.err, "ccd", "sampled-ccd");
  const std::string absolute = std::filesystem::absolute(testing::kExamplePlugin).lexically_normal().string();
  EXPECT_NE(replay.find("--plugin " + absolute + " --json"), std::string::npos) << replay;
  const json data = json::parse(testing::slurp(dir / "report.json"))["suites"][0]["data"];
  expect_replay_reproduces(r.err, "ccd", "sampled-ccd", ccd_counts(data, "sampled-ccd"), "queries");
  std::filesystem::remove_all(dir);
}

TEST(CliDisagreements, ATritriReplayOfOneEngineReproducesItsMissesAndFalseHits) {
  const auto dir = testing::temp_dir("disagree-tritri");
  const auto r = run_cli("suite tritri --quick --threads 2 --engines core-mt --out " + quoted(dir.string()));
  EXPECT_EQ(r.code, 0) << r.err;  // core-mt is reported, not checked
  const json report = json::parse(testing::slurp(dir / "report.json"));
  EngineCounts mt;
  for (const auto& [family, f] : report["suites"][0]["data"]["core-mt"].items()) {
    if (!f.is_object()) continue;
    mt.misses += f["misses"].get<long>();
    mt.false_hits += f["false_hits"].get<long>();
    EXPECT_EQ(f["agree"].get<long>() + f["misses"].get<long>() + f["false_hits"].get<long>() +
                  f["no_answer"].get<long>(),
              f["pairs"].get<long>()) << family;
  }
  ASSERT_GT(mt.misses, 0);  // the seed's AND of edge tests misses pairs pierced from one side only
  const std::string md = testing::slurp(dir / "report.md");
  EXPECT_NE(md.find("misses on "), std::string::npos);
  EXPECT_NE(md.find(" misses"), std::string::npos);
  expect_replay_reproduces(r.err, "tritri", "core-mt", mt, "pairs");
  std::filesystem::remove_all(dir);
}

TEST(CliDisagreements, APlaneReplayOfOneEngineReproducesItsMissesAndFalseHits) {
  const auto dir = testing::temp_dir("disagree-plane");
  const auto r = run_cli("suite plane --quick --threads 2 --out " + quoted(dir.string()));
  EXPECT_EQ(r.code, 0) << r.err;
  const json agreement = json::parse(testing::slurp(dir / "report.json"))["suites"][0]["data"]["agreement"];
  long found = 0;
  for (const auto& [engine, categories] : agreement.items()) {
    EngineCounts c;
    for (const auto& [category, t] : categories.items()) {
      if (!t.is_object()) continue;
      c.misses += t["misses"].get<long>();
      c.false_hits += t["false_hits"].get<long>();
    }
    found += c.misses + c.false_hits;
    expect_replay_reproduces(r.err, "plane", engine, c, "cases");
  }
  EXPECT_GT(found, 0);  // the seed's floating-point test decides border cases by rounding
  std::filesystem::remove_all(dir);
}

TEST(CliDisagreements, ALateTimeOfImpactFailsTheOutsideEnginesCheck) {
  const auto dir = testing::temp_dir("disagree-late");
  const std::string doors = " --engine-cmd " + quoted("late=" + testing::misbehaving_engine("ccd-late")) +
                            " --engine-cmd " + quoted("py=" + testing::kPythonEngine);
  const auto r = run_cli("suite ccd --quick --threads 2" + doors + " --engines late,py --out " + quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err;
  const json report = json::parse(testing::slurp(dir / "report.json"));
  for (const char* kind : {"vertex-face", "edge-edge"}) {
    const std::string family = std::string("ccd/") + kind + "/random/";
    const json* late = check_in(report, family + "late/max_toi_late");
    const json* py = check_in(report, family + "py/max_toi_late");
    ASSERT_TRUE(late && py) << kind;
    EXPECT_FALSE((*late)["pass"].get<bool>()) << late->dump();
    // The late engine answers the example's toi + 0.3: late by 0.3 wherever t* <= 0.7.
    EXPECT_NEAR((*late)["value"].get<double>(), 0.3, 1e-6) << late->dump();
    EXPECT_EQ((*late)["tolerance"], "/ccd/outside_random_max_toi_late");
    EXPECT_NE((*late)["note"].get<std::string>().find("later than the referee's first contact"), std::string::npos);
    EXPECT_TRUE((*py)["pass"].get<bool>()) << py->dump();
    // Its hits are the example's, which pass: only the time fails it.
    for (const char* what : {"false_negative_rate", "false_positive_rate", "unanswered_rate"}) {
      const json* c = check_in(report, family + "late/" + what);
      ASSERT_NE(c, nullptr) << what;
      EXPECT_TRUE((*c)["pass"].get<bool>()) << c->dump();
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
