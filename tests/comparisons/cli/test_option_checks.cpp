// The command line's values (comparisons/cli/option_checks.h): every numeric option of every
// subcommand out of its domain, every empty path, exits 2 with one line naming the option and
// the value, before any work and with nothing written. The issue's cases first: --dt 0 and
// --steps -1 used to run the scene's own values and exit 0.
#include "tests/support/rejection.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

using testing::expect_rejected;
using testing::run_cli;

class OptionChecks : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::temp_dir("options");
    testing::write_text(dir_ / "s.json", R"({"dt":0.01,"steps":10,"particles":[{"position":[0,0,0],"mass":1}]})");
    testing::write_text(dir_ / "pairs.json", R"({"pairs":[]})");
    testing::write_text(dir_ / "cases.json", R"({"cases":[]})");
    testing::write_text(dir_ / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const char* name) const { return "'" + (dir_ / name).string() + "'"; }
  std::string out() const { return " --out '" + (dir_ / "out").string() + "'"; }
  /// Runs `args`, expects the one-line rejection containing `message`, and no output directory.
  void expect(const std::string& args, const std::string& message) {
    expect_rejected(run_cli(args), {message}, args);
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out")) << args;
  }
  std::filesystem::path dir_;
};

TEST_F(OptionChecks, RunRejectsEveryValueOutOfItsDomain) {
  const std::string run = "run " + path("s.json") + out() + " ";
  expect(run + "--dt 0", "tecido: --dt: must be > 0 (got 0)");
  expect(run + "--dt -0.01", "--dt: must be > 0 (got -0.01)");
  expect(run + "--dt 11", "--dt: must be <= 10 (got 11)");
  expect(run + "--dt nan", "--dt: must be a finite number (got nan)");
  expect(run + "--dt inf", "--dt: must be a finite number (got inf)");
  expect(run + "--dt 0.01x", "--dt: must be a number (got \"0.01x\")");
  expect(run + "--steps -1", "tecido: --steps: must be in [0, 1000000000] (got -1)");
  expect(run + "--steps 1000000001", "--steps: must be in [0, 1000000000] (got 1000000001)");
  expect(run + "--steps 2.5", "--steps: must be an integer in [0, 1000000000] (got \"2.5\")");
  expect(run + "--steps 99999999999999999999", "--steps: must be an integer in [0, 1000000000]");
  expect(run + "--frame-every 0", "--frame-every: must be in [1, 1000000000] (got 0)");
  expect(run + "--frame-every -3", "--frame-every: must be in [1, 1000000000] (got -3)");
  expect(run + "--max-work 0", "--max-work: must be >= 1 (got 0)");
  expect(run + "--integrator verlet", "--integrator: must be one of euler, symplectic, midpoint, rk4 (got \"verlet\")");
  expect("run " + path("s.json") + " --out ''", "--out: must not be empty");
  expect("run ''", "scene: must not be empty");
  // Options that only mean something with --out are not silently ignored without it.
  expect("run " + path("s.json") + " --frame-every 5", "--frame-every requires --out");
  expect("run " + path("s.json") + " --vtk", "--vtk requires --out");
  // In range they apply: --steps 0 runs no step, --dt overrides the scene's.
  const auto r = run_cli("run " + path("s.json") + " --steps 0 --dt 0.5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"steps\":0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"dt\":0.5"), std::string::npos) << r.out;
}

TEST_F(OptionChecks, ExperimentSuiteAndMergeRejectEveryValueOutOfItsDomain) {
  const std::string exp = "experiment self-contact --quick" + out() + " ";
  expect(exp + "--threads -1", "--threads: must be in [0, 1024] (got -1)");
  expect(exp + "--threads 2000", "--threads: must be in [0, 1024] (got 2000)");
  expect(exp + "--strength -1", "--strength: must be >= 0 (got -1)");
  expect(exp + "--strength nan", "--strength: must be a finite number (got nan)");
  expect(exp + "--shard 2/2", "--shard: \"2/2\" is not i/n with 0 <= i < n <= 65536");
  expect(exp + "--shard -1/2", "--shard: \"-1/2\" is not i/n");
  expect(exp + "--shard 0/0", "--shard: \"0/0\" is not i/n");
  expect(exp + "--runs 0-2000000000", "--runs: \"0-2000000000\" is outside the runs (run indices are 0..71)");
  expect(exp + "--runs 72", "--runs: \"72\" is outside the runs (run indices are 0..71)");
  expect(exp + "--runs 5-3", "--runs: \"5-3\" is an empty range");
  expect(exp + "--runs x", "--runs: \"x\" is not an index or a range a-b");
  expect(exp + "--elasticity-as both", "--elasticity-as: must be one of stiffness, restitution (got \"both\")");
  expect(exp + "--max-work -5", "--max-work: must be >= 1 (got -5)");
  expect(exp + "--scene ''", "--scene: must not be empty");
  expect("experiment self-contact --quick --out ''", "--out: must not be empty");
  const std::string suite = "suite order" + out() + " ";
  expect(suite + "--seed -1", "--seed: must be an integer in [0, 18446744073709551615] (got \"-1\")");
  expect(suite + "--seed 18446744073709551616", "--seed: must be an integer in [0, 18446744073709551615]");
  expect(suite + "--seed 1e3", "--seed: must be an integer in [0, 18446744073709551615] (got \"1e3\")");
  expect(suite + "--threads -2", "--threads: must be in [0, 1024] (got -2)");
  expect(suite + "--shard 1/x", "--shard: \"1/x\" is not i/n");
  expect(suite + "--tolerances ''", "--tolerances: must not be empty");
  expect(suite + "--data ''", "--data: must not be empty");
  expect("merge " + path("s.json") + " --out ''", "--out: must not be empty");
  expect("merge ''" + out(), "dirs: must not be empty");
}

TEST_F(OptionChecks, QueryCommandsRejectEmptyPathsAndBadEngineLists) {
  expect("tritri --pairs '' --json", "--pairs: must not be empty");
  expect("plane --cases '' --json", "--cases: must not be empty");
  expect("selfcollide --mesh '' --json", "--mesh: must not be empty");
  expect("tritri --pairs " + path("pairs.json") + " --engines core,core --json", "--engines: \"core\" is named twice");
  expect("plane --cases " + path("cases.json") + " --engines , --json", "--engines: no plane engine given");
  expect("selfcollide --mesh " + path("m.obj") + " --engines bogus --json", "--engines: unknown self-collision engine \"bogus\"");
}

// CLI11's own errors keep the contract: one line, exit 2, the option named.
TEST_F(OptionChecks, ParseErrorsAreOneLineExitTwo) {
  expect("run " + path("s.json") + " --bogus", "The following argument was not expected: --bogus");
  expect("run " + path("s.json") + " --steps 5 --steps 7", "--steps: At Most 1 required but received 2");
  expect("run", "scene is required");
  expect("", "A subcommand is required");
  expect("frobnicate", "unknown command \"frobnicate\" (known: ccd, experiment, merge, plane, run, selfcollide, suite, tritri, view; see --help)");
}

}  // namespace
}  // namespace tecido
