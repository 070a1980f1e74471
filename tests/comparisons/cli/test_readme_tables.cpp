// README.md's verdict tables and speed goals are what scripts/readme_tables.py generates from the committed
// results docs/results/self_contact_experiment.json, docs/results/forced_contact/experiment.json and
// docs/results/bench/report.json: the script's --check passes on the
// repository, fails (exit 1, with a diff) when the README's block is edited by hand, and refuses
// (exit 2, one line naming the file) a README without the block or a result that is not one.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <string>

namespace tecido {
namespace {

namespace fs = std::filesystem;
const fs::path kTablesSourceDir = TECIDO_SOURCE_DIR;

testing::CliResult run_script(const std::string& args, const fs::path& dir) {
  const std::string cmd = "python3 " + testing::quoted((kTablesSourceDir / "scripts/readme_tables.py").string()) + " " + args +
                          " >" + testing::quoted((dir / "out").string()) + " 2>" + testing::quoted((dir / "err").string());
  const int status = std::system(cmd.c_str());
  testing::CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = testing::slurp(dir / "out");
  r.err = testing::slurp(dir / "err");
  return r;
}

std::string result_arg() { return "--result " + testing::quoted((kTablesSourceDir / "docs/results/self_contact_experiment.json").string()); }

TEST(ReadmeTables, TheReadmeQuotesTheCommittedResult) {
  const fs::path dir = testing::temp_dir("readme-tables-check");
  const auto r = run_script("--check", dir);
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string readme = testing::slurp(kTablesSourceDir / "README.md");
  EXPECT_NE(readme.find("<!-- self-contact-verdicts:begin -->"), std::string::npos);
  EXPECT_NE(readme.find("docs/results/self_contact_experiment.json"), std::string::npos);
  EXPECT_NE(readme.find("<!-- forced-contact-verdicts:begin -->"), std::string::npos);
  EXPECT_NE(readme.find("docs/results/forced_contact/experiment.json"), std::string::npos);
  EXPECT_NE(readme.find("<!-- speed-goals:begin -->"), std::string::npos);
  EXPECT_NE(readme.find("docs/results/bench/report.json"), std::string::npos);
}

/// A README with only the speed block's markers around `inside`, and the other two blocks as the
/// repository's README has them.
std::string readme_with_speed_block(const std::string& inside) {
  std::string readme = testing::slurp(kTablesSourceDir / "README.md");
  const std::size_t b = readme.find("<!-- speed-goals:begin -->"), e = readme.find("<!-- speed-goals:end -->");
  if (b == std::string::npos || e == std::string::npos) return "";
  return readme.substr(0, b) + "<!-- speed-goals:begin -->\n" + inside + "<!-- speed-goals:end -->" +
         readme.substr(e + std::string("<!-- speed-goals:end -->").size());
}

TEST(ReadmeTables, TheSpeedBlockSaysWhichGoalsAreMetFromTheReport) {
  const fs::path dir = testing::temp_dir("readme-tables-speed");
  const fs::path report = dir / "report.json";
  testing::write_text(report, R"({"tecido": {"command_line": "tecido suite bench --out x", "commit": "abc1234"},
    "suites": [{"name": "plane", "data": {}}, {"name": "bench", "data": {"goals": [
      {"id": "a", "what": "continuous / discrete", "value": 7.4, "target": 3, "comparison": "at_most", "unit": "", "met": false},
      {"id": "b", "what": "thread speed-up", "value": 1.8, "target": 1.7, "comparison": "at_least", "unit": "", "met": true},
      {"id": "c", "what": "flat frame", "value": null, "target": 15, "comparison": "at_most", "unit": "ms", "met": null}]}}]})");
  const fs::path copy = dir / "README.md";
  const std::string readme = readme_with_speed_block("typed by hand\n");
  ASSERT_FALSE(readme.empty()) << "README.md has no speed-goals block";
  testing::write_text(copy, readme);
  const std::string args = "--readme " + testing::quoted(copy.string()) + " --bench-result " + testing::quoted(report.string());
  const auto failed = run_script(args + " --check", dir);
  EXPECT_EQ(failed.code, 1);
  EXPECT_NE(failed.err.find("speed-goals block differs"), std::string::npos) << failed.err;
  ASSERT_EQ(run_script(args, dir).code, 0);
  std::string out = testing::slurp(copy);
  std::replace(out.begin(), out.end(), '\n', ' ');  // the paragraph is wrapped at 190 columns
  EXPECT_NE(out.find("at commit abc1234"), std::string::npos) << out;
  EXPECT_NE(out.find("1 of 3 speed goals met"), std::string::npos) << out;
  EXPECT_NE(out.find("Not met (measured, goal): `a` 7.4 (≤ 3); `c` not measured (≤ 15 ms). The other 1 are met."), std::string::npos) << out;
  EXPECT_EQ(out.find("typed by hand"), std::string::npos);
  EXPECT_EQ(run_script(args + " --check", dir).code, 0);
}

TEST(ReadmeTables, ABenchReportWithoutGoalsExitsTwoNamingThePath) {
  const fs::path dir = testing::temp_dir("readme-tables-speed-bad");
  const fs::path report = dir / "report.json";
  testing::write_text(report, R"({"suites": [{"name": "plane", "data": {}}]})");
  const auto r = run_script("--check --bench-result " + testing::quoted(report.string()), dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("report.json: /suites: no bench suite"), std::string::npos) << r.err;
  testing::write_text(report, R"({"suites": [{"name": "bench", "data": {"goals": [{"id": "a", "what": "x", "value": 1,
    "target": 2, "comparison": "at_most", "unit": ""}]}}]})");
  const auto r2 = run_script("--check --bench-result " + testing::quoted(report.string()), dir);
  EXPECT_EQ(r2.code, 2);
  EXPECT_NE(r2.err.find("report.json: /suites/0/data/goals/0: no \"met\""), std::string::npos) << r2.err;
}

TEST(ReadmeTables, AHandEditedForcedContactTableFailsTheCheck) {
  const fs::path dir = testing::temp_dir("readme-tables-edit-forced");
  std::string readme = testing::slurp(kTablesSourceDir / "README.md");
  const std::size_t at = readme.find("| `gia-recovers`", readme.find("<!-- forced-contact-verdicts:begin -->"));
  ASSERT_NE(at, std::string::npos);
  readme.replace(at, 16, "| `gia-RECOVERS`");
  const fs::path copy = dir / "README.md";
  testing::write_text(copy, readme);
  const auto failed = run_script("--readme " + testing::quoted(copy.string()) + " " + result_arg() + " --check", dir);
  EXPECT_EQ(failed.code, 1);
  EXPECT_NE(failed.err.find("gia-RECOVERS"), std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find("forced-contact block differs"), std::string::npos) << failed.err;
}

TEST(ReadmeTables, AHandEditedTableFailsTheCheckAndIsRewritten) {
  const fs::path dir = testing::temp_dir("readme-tables-edit");
  std::string readme = testing::slurp(kTablesSourceDir / "README.md");
  const std::size_t at = readme.find("reproduced", readme.find("<!-- self-contact-verdicts:begin -->"));
  ASSERT_NE(at, std::string::npos);
  readme.replace(at, 10, "REPRODUCED");
  const fs::path copy = dir / "README.md";
  testing::write_text(copy, readme);
  const std::string args = "--readme " + testing::quoted(copy.string()) + " " + result_arg();
  const auto failed = run_script(args + " --check", dir);
  EXPECT_EQ(failed.code, 1);
  EXPECT_NE(failed.err.find("REPRODUCED"), std::string::npos) << failed.err;  // the diff shows the edit
  EXPECT_EQ(testing::slurp(copy), readme) << "--check writes nothing";
  EXPECT_EQ(run_script(args, dir).code, 0);
  EXPECT_EQ(testing::slurp(copy), testing::slurp(kTablesSourceDir / "README.md"));
  EXPECT_EQ(run_script(args + " --check", dir).code, 0);
}

TEST(ReadmeTables, BadInputExitsTwoNamingTheFile) {
  const fs::path dir = testing::temp_dir("readme-tables-bad");
  const fs::path no_block = dir / "README.md";
  testing::write_text(no_block, "# a README without the block\n");
  const auto r = run_script("--readme " + testing::quoted(no_block.string()) + " " + result_arg(), dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(no_block.string()), std::string::npos) << r.err;
  EXPECT_EQ(testing::slurp(no_block), "# a README without the block\n");
  const fs::path not_result = dir / "x.json";
  testing::write_text(not_result, "{\"experiment\": \"other\"}");
  const auto r2 = run_script("--check --result " + testing::quoted(not_result.string()), dir);
  EXPECT_EQ(r2.code, 2);
  EXPECT_NE(r2.err.find("x.json: /experiment"), std::string::npos) << r2.err;
}

}  // namespace
}  // namespace tecido
