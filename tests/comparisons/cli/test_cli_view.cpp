// The pages the CLI writes: `tecido view` on a user's file (bad input: one line, exit 2, nothing
// written; markup in an id lands in the data file as a JSON string, never in the HTML), `tecido run
// --out` (index.html beside the frames). The pages themselves are tested in a browser
// (web/test/run_all.mjs, scripts/browser_test.sh).
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tecido
