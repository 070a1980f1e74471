// The obstacles suite through the CLI with every band of its tolerance section changed: the same
// checks, the same work (data apart from timings), and pass or fail as the bands say.
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace tecido::suites {
namespace {

using testing::run_cli;

#ifdef TECIDO_SANITIZED
#define TECIDO_SKIP_UNDER_ASAN GTEST_SKIP() << "three quick suite runs take minutes under AddressSanitizer"
#else
#define TECIDO_SKIP_UNDER_ASAN (void)0
#endif

TEST(ObstaclesSuite, EveryToleranceChangedSameChecksSameWork) {
  TECIDO_SKIP_UNDER_ASAN;
  const auto dir = testing::temp_dir("obstacles-tolerances");
  const auto q = [](const std::filesystem::path& p) { return "'" + p.string() + "'"; };
  const auto base = run_cli("suite obstacles --quick --out " + q(dir / "base"));
  ASSERT_EQ(base.code, 0) << base.err;
  const auto want = nlohmann::json::parse(testing::slurp(dir / "base" / "report.json"));
  ASSERT_FALSE(testing::check_names(want).empty());
  // Wide: every band twice as wide plus 10 (every check still holds). Negative: every band
  // [0, -1 - x] is empty, so every check fails.
  ASSERT_GT(testing::write_changed_tolerances(dir / "wide.json", {"obstacles"}, [](double x) { return 2 * x + 10; }), 0);
  testing::write_changed_tolerances(dir / "negative.json", {"obstacles"}, [](double x) { return -1.0 - x; });
  for (const char* name : {"wide", "negative"}) {
    const auto r = run_cli("suite obstacles --quick --tolerances " + q(dir / (std::string(name) + ".json")) + " --out " +
                           q(dir / name));
    const auto got = nlohmann::json::parse(testing::slurp(dir / name / "report.json"));
    EXPECT_EQ(testing::check_names(got), testing::check_names(want)) << name;
    EXPECT_EQ(testing::data_without_timings(got), testing::data_without_timings(want)) << name << ": other work";
    const bool fail = std::string(name) == "negative";
    EXPECT_EQ(r.code, fail ? 1 : 0) << name << ": " << r.err;
    for (const auto& c : got["suites"][0]["checks"]) EXPECT_EQ(c["pass"].get<bool>(), !fail) << c.dump();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites
