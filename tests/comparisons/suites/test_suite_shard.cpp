// The sweep suites (comparisons/suites/sweep.h) sharded with `tecido suite NAME --shard i/n` and
// joined with `tecido merge`: the merged report is the unsharded run's, byte for byte, except for
// wall-clock fields (a suite's seconds, tritri's ns per pair; the tradeoff suite's costs and the
// Pareto front they decide come from the shards); inconsistent shards exit 2 with one line. Also the sweep runner's
// independence from the thread count and the lossless JSON of doubles.
#include "tests/support/cli_runner.h"
#include "tests/support/command_line_mask.h"
#include "comparisons/suites/random.h"
#include "comparisons/io/input_error.h"
#include "comparisons/suites/report.h"
#include "comparisons/suites/suite_shard.h"
#include "comparisons/suites/sweep.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <regex>
#include <sstream>

namespace tecido::suites {
namespace {

using testing::run_cli;

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

/// JSON without its wall-clock fields: every "seconds" and "ns_per_pair" key.
nlohmann::json mask_timings(nlohmann::json j) {
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (auto it = j.begin(); it != j.end(); ++it)
      if (it.key() != "seconds" && it.key() != "ns_per_pair") out[it.key()] = mask_timings(it.value());
    return out;
  }
  if (j.is_array())
    for (auto& v : j) v = mask_timings(v);
  return j;
}

/// report.json without its wall-clock fields (every "seconds" and "ns_per_pair" key), nor the
/// command line that wrote it (the run's, the merge's).
nlohmann::json mask_json(const nlohmann::json& j) { return mask_timings(testing::mask_command_line_json(j)); }

/// report.md without its wall-clock cells (the summary's time column and tritri's ns/pair column)
/// nor its command line.
std::string mask_md(const std::string& md) {
  std::istringstream in(testing::mask_command_line_md(md));
  std::string line, out, section;
  const std::regex summary_time(R"(( \| )[0-9.]+( \|)$)");
  const std::regex ns_cell(R"(^(\| [a-z-]+ \| )[0-9]+( \|))");
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) section = line;
    if (section.empty() && (line.rfind("| stability |", 0) == 0 || line.rfind("| tritri |", 0) == 0))
      line = std::regex_replace(line, summary_time, "$1*$2");
    if (section == "## tritri") line = std::regex_replace(line, ns_cell, "$1*$2");
    out += line + "\n";
  }
  return out;
}

TEST(SuiteShard, MergedShardsEqualTheUnshardedRun) {
  const auto dir = testing::temp_dir("suite-shard");
  const std::string suites = "suite stability tritri --quick";
  const auto full = run_cli(suites + " --threads 2 --out " + q(dir / "full"));
  ASSERT_EQ(full.code, 0) << full.err;
  const std::string want_json = mask_json(nlohmann::json::parse(testing::slurp(dir / "full" / "report.json"))).dump(1);
  const std::string want_md = mask_md(testing::slurp(dir / "full" / "report.md"));
  ASSERT_NE(want_md.find("## tritri"), std::string::npos);

  for (int n : {2, 3}) {
    std::string shards;
    for (int i = n - 1; i >= 0; --i) {  // any order on the merge's command line
      const auto sd = dir / ("s" + std::to_string(i) + "of" + std::to_string(n));
      const auto r = run_cli(suites + " --threads 1 --shard " + std::to_string(i) + "/" + std::to_string(n) + " --out " + q(sd));
      ASSERT_EQ(r.code, 0) << r.err;
      EXPECT_TRUE(r.err.empty()) << "no progress bar when stderr is not a terminal: " << r.err;
      EXPECT_FALSE(std::filesystem::exists(sd / "report.md"));
      const auto j = nlohmann::json::parse(testing::slurp(sd / "shard.json"));
      EXPECT_EQ(j["shard"], nlohmann::json::array({i, n}));
      for (const auto& s : j["suites"])
        for (const auto& c : s["results"]) EXPECT_EQ(c["index"].get<int>() % n, i);
      shards += " " + q(sd);
    }
    const auto out = dir / ("merged" + std::to_string(n));
    const auto m = run_cli("merge" + shards + " --out " + q(out));
    ASSERT_EQ(m.code, 0) << m.err;
    EXPECT_EQ(mask_json(nlohmann::json::parse(testing::slurp(out / "report.json"))).dump(1), want_json) << n;
    EXPECT_EQ(mask_md(testing::slurp(out / "report.md")), want_md) << n;
    EXPECT_EQ(testing::slurp(out / "tritri" / "disagreements.json"), testing::slurp(dir / "full" / "tritri" / "disagreements.json"));
  }
  std::filesystem::remove_all(dir);
}

TEST(SuiteShard, InconsistentShardsExitTwo) {
  const auto dir = testing::temp_dir("suite-shard-bad");
  const std::string suites = "suite stability --quick --threads 2";
  ASSERT_EQ(run_cli(suites + " --shard 0/2 --out " + q(dir / "s0")).code, 0);
  ASSERT_EQ(run_cli(suites + " --shard 1/2 --out " + q(dir / "s1")).code, 0);
  ASSERT_EQ(run_cli(suites + " --shard 1/3 --out " + q(dir / "t1")).code, 0);
  const auto shard1 = nlohmann::json::parse(testing::slurp(dir / "s1" / "shard.json"));
  auto edited = [&](const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = shard1;
    edit(j);
    std::filesystem::create_directories(dir / name);
    testing::write_text(dir / name / "shard.json", j.dump());
    return q(dir / name);
  };
  const std::string s0 = q(dir / "s0"), s1 = q(dir / "s1");
  const std::string other_seed = edited("seed", [](nlohmann::json& j) { j["settings"]["seed"] = 7; });
  const std::string other_tol =
      edited("tol", [](nlohmann::json& j) { j["settings"]["tolerances"]["contents"]["stability"]["ratio_lo"] = 0.5; });
  const std::string missing = edited("missing", [](nlohmann::json& j) { j["suites"][0]["results"].erase(2); });
  const std::string twice =
      edited("twice", [](nlohmann::json& j) { j["suites"][0]["results"].push_back(j["suites"][0]["results"][0]); });
  const std::string misplaced = edited("misplaced", [](nlohmann::json& j) { j["suites"][0]["results"][0]["index"] = 0; });
  const std::string counts = edited("counts", [](nlohmann::json& j) { j["suites"][0]["cases"] = 1000; });
  const std::string broken = edited("broken", [](nlohmann::json& j) { j["suites"][0]["results"][0]["result"] = 1; });
  std::filesystem::create_directories(dir / "exp");
  testing::write_text(dir / "exp" / "experiment.json", R"({"shard":[1,2],"experiment":"self-contact"})");
  struct Case {
    std::string args, says;
  };
  const Case cases[] = {
      {s0 + " " + s1 + " " + s0, "given twice"},
      {s1, "shard 0/2 is missing"},
      {s0 + " " + q(dir / "t1"), "does not belong"},
      {s0 + " " + other_seed, "other settings"},
      {s0 + " " + other_tol, "other settings"},
      {s0 + " " + missing, "is missing"},
      {s0 + " " + twice, "appears twice"},
      {s0 + " " + misplaced, "belongs to shard 0/2"},
      {s0 + " " + counts, "case counts"},
      {s0 + " " + broken, "cannot read"},
      {s0 + " " + q(dir / "exp"), "one kind at a time"},
      {s0 + " " + q(dir / "nonexistent"), ""},
  };
  for (const auto& c : cases) {
    const auto r = run_cli("merge " + c.args + " --out " + q(dir / "never"));
    EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "never"));

  // Usage: a suite that is not split into cases, a bad shard.
  for (const std::string args : {"suite bench --quick --shard 0/2", "suite stability --quick --shard 2/2",
                                 "suite stability --quick --shard 1"}) {
    const auto r = run_cli(args + " --out " + q(dir / "never"));
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "never"));
  std::filesystem::remove_all(dir);
}

/// Re-cuts suite shard files into n shards (the same case results, other slices; the suites' wall
/// seconds summed into shard 0, so the merge's sum is unchanged).
void recut(const std::vector<std::filesystem::path>& from, int n, const std::filesystem::path& to) {
  nlohmann::json base;
  std::vector<std::vector<nlohmann::json>> results;  // per suite, by case index
  std::vector<double> seconds;
  for (const auto& f : from) {
    const auto j = nlohmann::json::parse(testing::slurp(f / "shard.json"));
    if (base.is_null()) {
      base = j;
      for (const auto& s : j["suites"]) results.emplace_back(s["cases"].get<std::size_t>());
      seconds.assign(results.size(), 0.0);
    }
    for (std::size_t s = 0; s < j["suites"].size(); ++s) {
      seconds[s] += j["suites"][s]["seconds"].get<double>();
      for (const auto& c : j["suites"][s]["results"]) results[s][c["index"].get<std::size_t>()] = c;
    }
  }
  for (int i = 0; i < n; ++i) {
    nlohmann::json j = base;
    j["shard"] = {i, n};
    for (std::size_t s = 0; s < results.size(); ++s) {
      j["suites"][s]["seconds"] = i == 0 ? seconds[s] : 0.0;
      j["suites"][s]["results"] = nlohmann::json::array();
      for (std::size_t k = static_cast<std::size_t>(i); k < results[s].size(); k += static_cast<std::size_t>(n))
        j["suites"][s]["results"].push_back(results[s][k]);
    }
    std::filesystem::create_directories(to / std::to_string(i));
    testing::write_text(to / std::to_string(i) / "shard.json", j.dump());
  }
}

// The tradeoff suite times its runs, so two runs differ in their costs and in the Pareto front
// those decide. One real computation (two shards) is therefore merged as cut, re-joined into one
// shard and re-cut into three: the three reports must be identical byte for byte, timings
// included (the merge uses the shards' measurements). That the sweep's merge equals its unsharded
// run is the same code path as MergedShardsEqualTheUnshardedRun above. About 5 s in a release
// build: skipped under AddressSanitizer, where it takes minutes.
TEST(SuiteShard, TradeoffMergeDoesNotDependOnTheSlicing) {
#ifdef TECIDO_SANITIZED
  GTEST_SKIP() << "too slow under AddressSanitizer";
#endif
  const auto dir = testing::temp_dir("suite-shard-tradeoff");
  ASSERT_EQ(run_cli("suite tradeoff --quick --shard 0/2 --out " + q(dir / "s0")).code, 0);
  ASSERT_EQ(run_cli("suite tradeoff --quick --shard 1/2 --out " + q(dir / "s1")).code, 0);
  const auto m = run_cli("merge " + q(dir / "s1") + " " + q(dir / "s0") + " --out " + q(dir / "m2"));
  ASSERT_EQ(m.code, 0) << m.err << m.out;
  recut({dir / "s0", dir / "s1"}, 1, dir / "one");
  recut({dir / "s0", dir / "s1"}, 3, dir / "three");
  ASSERT_EQ(run_cli("merge " + q(dir / "one" / "0") + " --out " + q(dir / "m1")).code, 0);
  ASSERT_EQ(run_cli("merge " + q(dir / "three" / "2") + " " + q(dir / "three" / "0") + " " + q(dir / "three" / "1") +
                    " --out " + q(dir / "m3"))
                .code,
            0);
  // Each merge records its own command line: masked in the reports.
  const auto masked = [&](const std::filesystem::path& m, const std::string& f) {
    const std::string text = testing::slurp(m / f);
    if (f == "report.json") return testing::mask_command_line(text);
    return f == "report.md" ? testing::mask_command_line_md(text) : text;
  };
  for (const char* f : {"report.json", "report.md", "tradeoff/cloth16.dat", "tradeoff/cloth32.dat"}) {
    const std::string want = masked(dir / "m2", f);
    ASSERT_FALSE(want.empty()) << f;
    EXPECT_EQ(masked(dir / "m1", f), want) << f;
    EXPECT_EQ(masked(dir / "m3", f), want) << f;
  }
  // The merged report uses the shards' measurements: every counted run has a cost.
  const auto got = nlohmann::json::parse(testing::slurp(dir / "m2" / "report.json"));
  for (const auto& run : got["suites"][0]["data"]["cloth16"]["runs"]) {
    if (run["counted"].get<bool>()) {
      EXPECT_GT(run["seconds"].get<double>(), 0.0);
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(Sweep, ResultsDoNotDependOnThreadsOrShards) {
  // A synthetic sweep: case k draws from its own substream.
  Sweep s;
  s.cases = 37;
  s.run_case = [](std::size_t k) {
    Rng r(substream(99, k));
    double sum = 0.0;
    for (int i = 0; i < 1000; ++i) sum += r.unit();
    return io::Json{{"k", k}, {"sum", num(sum)}};
  };
  std::vector<std::size_t> all(s.cases);
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  const auto one = run_sweep_cases(s, all, 1, "t", false);
  const auto four = run_sweep_cases(s, all, 4, "t", false);
  ASSERT_EQ(one.size(), s.cases);
  EXPECT_EQ(one, four);
  std::vector<io::Json> joined(s.cases);
  for (int i = 0; i < 3; ++i) {
    const auto idx = shard_indices(s.cases, i, 3);
    const auto part = run_sweep_cases(s, idx, 2, "t", false);
    for (std::size_t k = 0; k < idx.size(); ++k) {
      EXPECT_EQ(idx[k] % 3, static_cast<std::size_t>(i));
      joined[idx[k]] = part[k];
    }
  }
  EXPECT_EQ(joined, one);
}

TEST(Sweep, ACaseErrorBecomesItsResultAndBadInputEndsTheRun) {
  Sweep s;
  s.cases = 5;
  s.run_case = [](std::size_t k) -> io::Json {
    if (k == 3) throw std::runtime_error("case 3 broke");
    return k;
  };
  const std::vector<io::Json> r = run_sweep_cases(s, {0, 1, 2, 3, 4}, 2, "t", false);
  ASSERT_EQ(r.size(), 5u);
  for (std::size_t k : {0u, 1u, 2u, 4u}) {
    EXPECT_EQ(r[k], io::Json(k));
    EXPECT_EQ(case_error(r[k]), nullptr);
  }
  ASSERT_NE(case_error(r[3]), nullptr);
  EXPECT_NE(case_error(r[3])->find("case 3 broke"), std::string::npos) << *case_error(r[3]);

  // A data file the case reads that is bad is the user's input: exit 2, not a failed check.
  s.run_case = [](std::size_t k) -> io::Json {
    if (k == 1) throw io::InputError("scene.json", "/dt", "expected a number");
    return k;
  };
  EXPECT_THROW(run_sweep_cases(s, {0, 1, 2}, 2, "t", false), io::InputError);
}

TEST(CheckList, EveryDeclaredCheckIsReportedAndAMissingValueFails) {
  Tolerances tol(io::Json::parse(R"({"s":{"max":2.0,"lo":0.5,"hi":1.5,"w":0.1}})"), "tol.json");
  CheckList checks;
  checks.declare("s/a", tol.at_most("/s/max"));
  checks.declare("s/b", tol.between("/s/lo", "/s/hi"));
  checks.declare("s/c", tol.around("/s/w", 4.0));
  checks.declare("s/group/d", tol.at_least("/s/lo", 1.0));
  checks.declare("s/group/e", tol.at_least("/s/lo", 1.0));
  checks.declare("s/f", tol.at_most("/s/max", 3.0));
  EXPECT_THROW(checks.declare("s/a", tol.at_most("/s/max")), std::logic_error);
  checks.set("s/a", 1.0);
  checks.set("s/b", std::nan(""));
  checks.fail("s/c", "unstable at step 12");
  checks.fail_pending("s/group/", "case 3 threw: boom");
  EXPECT_THROW(checks.set("s/a", 1.0), std::logic_error);
  EXPECT_THROW(checks.set("s/undeclared", 1.0), std::logic_error);
  const std::vector<Check> c = checks.finish();
  ASSERT_EQ(c.size(), 6u);
  EXPECT_TRUE(c[0].pass);
  EXPECT_EQ(c[0].tolerance, "/s/max");
  EXPECT_FALSE(c[1].pass);
  EXPECT_EQ(c[1].reason, "value is NaN");
  EXPECT_FALSE(c[2].pass);
  EXPECT_EQ(c[2].reason, "unstable at step 12");
  EXPECT_DOUBLE_EQ(c[2].lo, 3.9);
  EXPECT_DOUBLE_EQ(c[2].hi, 4.1);
  EXPECT_FALSE(c[3].pass);
  EXPECT_FALSE(c[4].pass);
  EXPECT_EQ(c[4].reason, "case 3 threw: boom");
  EXPECT_FALSE(c[5].pass);
  EXPECT_EQ(c[5].reason, "not produced");
  EXPECT_DOUBLE_EQ(c[5].hi, 6.0);
  // The report keeps all six and says why each failed.
  SuiteResult r;
  r.name = "s";
  r.checks = c;
  SuiteContext ctx;
  ctx.tolerances = &tol;
  const io::Json j = report_json({r}, ctx);
  ASSERT_EQ(j["suites"][0]["checks"].size(), 6u);
  EXPECT_TRUE(j["suites"][0]["checks"][1]["value"].is_null());
  EXPECT_EQ(j["suites"][0]["checks"][5]["reason"], "not produced");
  const std::string md = report_markdown({r}, ctx);
  EXPECT_NE(md.find("unstable at step 12"), std::string::npos);
  EXPECT_NE(md.find("not produced"), std::string::npos);
}

TEST(Sweep, DoublesRoundTripThroughText) {
  const double values[] = {0.1,
                           -0.0,
                           1.0 / 3.0,
                           std::nextafter(1.0, 2.0),
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           -std::numeric_limits<double>::min(),
                           1e300 * 1e10,
                           -1e300 * 1e10,
                           std::nan("")};
  for (double x : values) {
    const double y = get_num(io::Json::parse(num(x).dump()));
    if (std::isnan(x)) {
      EXPECT_TRUE(std::isnan(y));
    } else {
      EXPECT_EQ(std::memcmp(&x, &y, sizeof x), 0) << x;
    }
  }
  const std::vector<Vec3> xs = {Vec3(0.1, -2.5e-300, 7), Vec3(1.0 / 7.0, 0, -0.0)};
  const auto back = vec3s_from_json(io::Json::parse(vec3s_json(xs).dump()));
  ASSERT_EQ(back.size(), xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) EXPECT_EQ(std::memcmp(back[i].data(), xs[i].data(), 3 * sizeof(double)), 0);
  const Check c = make_check("a/b", 0.30000000000000004, 0.1, 0.3, "note");
  const Check d = check_from_json(io::Json::parse(check_json(c).dump()));
  EXPECT_EQ(d.name, c.name);
  EXPECT_EQ(d.value, c.value);
  EXPECT_EQ(d.pass, c.pass);
  EXPECT_EQ(d.note, c.note);
}

}  // namespace
}  // namespace tecido::suites
