// The obstacles suite through the CLI with every band of its tolerance section changed: the same
// checks, the same work (data apart from timings), and pass or fail as the bands say. And its block
// runs' pages: one per block run beside the report, their data out of report.json; a block run's
// view holds the scene's start and every counted frame.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/obstacles/block_case.h"
#include "comparisons/suites/obstacles/block_scene.h"
#include "comparisons/suites/obstacles/settings.h"
#include "comparisons/view/base64.h"
#include "tests/support/cli_runner.h"
#include "tests/support/tolerance_file.h"

#include <gtest/gtest.h>
#include <algorithm>
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
  const auto& data = want["suites"][0]["data"];
  int blocks = 0;
  for (const auto& [name, result] : data.items()) {
    if (name.rfind("block/", 0) != 0) continue;
    ++blocks;
    EXPECT_FALSE(result.contains("view")) << name;  // the page's data stays out of report.json
    std::string file = name;
    std::replace(file.begin(), file.end(), '/', '-');
    for (const std::string ext : {".html", ".data.js"})
      EXPECT_TRUE(std::filesystem::exists(dir / "base" / "obstacles" / (file + ext))) << file << ext;
    EXPECT_NE(testing::slurp(dir / "base" / "report.md").find("obstacles/" + file + ".html"), std::string::npos) << file;
  }
  EXPECT_EQ(blocks, 4);  // 11 and 22, edges off and on
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

TEST(ObstaclesSuite, ABlockRunsViewHoldsTheStartAndEveryCountedFrame) {
  const obstacles::Settings s = obstacles::settings(true);
  const std::string data_dir = std::string(TECIDO_SOURCE_DIR) + "/data";
  const io::Json r = obstacles::block_case(s, data_dir, 11, false);
  const io::Json& v = r.at("view");
  EXPECT_EQ(v["kind"], "run");
  ASSERT_EQ(v["frames"].get<std::size_t>(), r["frames"].size() + 1);
  EXPECT_EQ(r["frames"].size(), static_cast<std::size_t>(s.block_frames));
  EXPECT_EQ(v["steps"][0], 0);
  for (std::size_t k = 0; k < r["frames"].size(); ++k) EXPECT_EQ(v["times"][k + 1], r["frames"][k][0]) << k;
  // The first frame is the scene's start, as float32.
  const Scene scene = obstacles::block_scene(s, data_dir, 11, false);
  std::vector<float> x0;
  for (const Vec3& p : scene.particles.x)
    for (int c = 0; c < 3; ++c) x0.push_back(static_cast<float>(p[c]));
  EXPECT_EQ(v["nodes"], 121);
  EXPECT_EQ(v["positions"].get<std::string>().substr(0, 121 * 12 * 4 / 3), view::float32_base64(x0));
}

}  // namespace
}  // namespace tecido::suites
