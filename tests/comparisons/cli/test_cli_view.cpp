// The pages the CLI writes: `tecido view` on a user's file (bad input: one line, exit 2, nothing
// written; markup in an id lands in the data file as a JSON string, never in the HTML), `tecido run
// --out` (index.html beside the frames), `tecido experiment self-contact --runs LIST --view` (a run's
// page per cell, the options it refuses). The pages themselves are tested in a browser
// (web/test/run_all.mjs, scripts/browser_test.sh).
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

namespace tecido {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_cli;

const char* const kHostileCases =
    R"({"cases":[{"id":"<img src=x onerror=alert(1)>","plane":{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],)"
    R"("half_extents":[1,1]},"from":[0,0,1],"to":[0,0,-1],"engine":"</script><script>alert(2)</script>",)"
    R"("answer":{"hit":"yes"},"referee":{"hit":true,"t":0.5}}]})";

TEST(CliView, CasesFileBecomesAPageWithItsTextAsData) {
  const auto dir = testing::temp_dir("view-cases");
  testing::write_text(dir / "cases.json", kHostileCases);
  const auto r = run_cli("view --cases " + quoted((dir / "cases.json").string()) + " --out " + quoted((dir / "page").string()));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = testing::slurp(dir / "page" / "view.html");
  EXPECT_NE(html.find("script-src 'self'"), std::string::npos);
  const std::string data = testing::slurp(dir / "page" / "view.data.js");
  // The id is a JSON string in a script of its own (shown by the viewer with textContent), never HTML.
  EXPECT_NE(data.find("\"id\":\"<img src=x onerror=alert(1)>\""), std::string::npos) << data;
  EXPECT_EQ(html.find("<img"), std::string::npos);
  // Labels of the wrong type are not carried ("hit": "yes"); well-typed ones are.
  EXPECT_EQ(data.find("\"answer\""), std::string::npos) << data;
  EXPECT_NE(data.find("\"referee\":{\"hit\":true,\"t\":0.5}"), std::string::npos) << data;
  fs::remove_all(dir);
}

TEST(CliView, BadFileIsOneLineExitTwoNothingWritten) {
  const auto dir = testing::temp_dir("view-bad");
  testing::write_text(dir / "pairs.json", R"({"pairs":[{"id":"p","a":[[0,0,0],[1,0,0]],"b":[[0,0,0],[1,0,0],[0,1,0]]}]})");
  const auto r = run_cli("view --pairs " + quoted((dir / "pairs.json").string()) + " --out " + quoted((dir / "page").string()));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("pairs.json: /pairs/0/a"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "page"));
  const auto none = run_cli("view --out " + quoted((dir / "page").string()));
  EXPECT_EQ(none.code, 2);
  EXPECT_FALSE(fs::exists(dir / "page"));
  fs::remove_all(dir);
}

TEST(CliView, RunWritesIndexHtmlBesideItsFrames) {
  const auto dir = testing::temp_dir("view-run");
  const auto r = run_cli("run " + quoted(std::string(TECIDO_SOURCE_DIR) + "/data/scenes/seed_fig10_12_block_121.json") +
                         " --steps 20 --out " + quoted((dir / "out").string()));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"index.html", "index.data.js"}) EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  const std::string data = testing::slurp(dir / "out" / "index.data.js");
  EXPECT_EQ(data.rfind("window.TECIDO_VIEW = {", 0), 0u);
  EXPECT_NE(data.find("\"frames\":21"), std::string::npos);
  fs::remove_all(dir);
}

/// A page's data: the JSON of its NAME.data.js.
nlohmann::json page_data(const fs::path& file) {
  const std::string js = testing::slurp(file);
  const std::string head = "window.TECIDO_VIEW = ";
  EXPECT_EQ(js.rfind(head, 0), 0u);
  return nlohmann::json::parse(js.substr(head.size(), js.rfind(';') - head.size()));
}

TEST(CliView, ExperimentViewWritesEachCellsFirstRunAsAPage) {
  const auto dir = testing::temp_dir("view-experiment");
  const auto r = run_cli("experiment self-contact --quick --runs 0,5 --view --out " + quoted((dir / "out").string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "experiment.json"));  // the ensemble did not run
  // Cell 0: step 0.02 s, a frame every step over --quick's 2 s, and the start. Cell 5: 0.02 s too (mode 1).
  for (const char* cell : {"0", "5"}) {
    ASSERT_TRUE(fs::exists(dir / "out" / "runs" / cell / "index.html")) << cell;
    const auto data = page_data(dir / "out" / "runs" / cell / "index.data.js");
    EXPECT_EQ(data["kind"], "run");
    EXPECT_EQ(data["frames"], 101) << cell;
    EXPECT_EQ(data["steps"][100], 100);
    EXPECT_DOUBLE_EQ(data["times"][100].get<double>(), 2.0);
    EXPECT_EQ(data["nodes"], 256);  // the fig. 21 cloth, 16 x 16
    EXPECT_NE(data["title"].get<std::string>().find("run " + std::string(cell)), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(CliView, ExperimentViewNeedsRunsAndRefusesShardsCalibrationAndForcedContact) {
  const auto dir = testing::temp_dir("view-experiment-options");
  const std::string out = " --out " + quoted((dir / "out").string());
  for (const std::string args : {"self-contact --quick --view", "self-contact --quick --runs 0 --view --shard 0/2",
                                 "self-contact --quick --runs 0 --view --calibrate", "forced-contact --quick --view"}) {
    const auto r = run_cli("experiment " + args + out);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("--view"), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "runs")) << args;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tecido
