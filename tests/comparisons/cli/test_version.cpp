// `tecido --version`, and the version, commit and command line in every file a command writes
// for later reading: report.json and report.md (suite), result.json (run --out), experiment.json.
#include "comparisons/io/source_dir.h"
#include "comparisons/io/provenance.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace tecido {
namespace {

using nlohmann::json;
using testing::run_cli;

json expected_provenance(const std::string& args) {
  return {{"version", io::tecido_version()}, {"commit", io::tecido_commit()},
          {"command_line", io::shell_line({TECIDO_CLI}) + " " + args}};
}

TEST(Version, PrintsVersionAndCommitAndExitsZero) {
  const auto r = run_cli("--version");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, io::version_line() + "\n");
  EXPECT_EQ(r.err, "");
  EXPECT_NE(run_cli("--help").out.find("--version"), std::string::npos);
}

TEST(Version, RunResultFileNamesItsProvenanceStdoutStaysTheResult) {
  const auto dir = testing::temp_dir("provenance-run");
  const std::string scene = std::string(TECIDO_SOURCE_DIR) + "/data/scenes/bounce_restitution.json";
  const std::string args = "run " + scene + " --json --steps 10 --out " + (dir / "out").string();
  const auto r = run_cli(args);
  ASSERT_EQ(r.code, 0) << r.err;
  const json file = json::parse(testing::slurp(dir / "out" / "result.json"));
  EXPECT_EQ(file["tecido"], expected_provenance(args));
  json stdout_result = json::parse(r.out);
  EXPECT_FALSE(stdout_result.contains("tecido"));
  json without = file;
  without.erase("tecido");
  EXPECT_EQ(without, stdout_result);  // otherwise the same result
  std::filesystem::remove_all(dir);
}

TEST(Version, SuiteReportsNameTheirProvenance) {
  const auto dir = testing::temp_dir("provenance-suite");
  const std::string args = "suite order --quick --threads 2 --out " + (dir / "out").string();
  const auto r = run_cli(args);
  ASSERT_TRUE(r.code == 0 || r.code == 1) << r.err;
  EXPECT_EQ(json::parse(testing::slurp(dir / "out" / "report.json"))["tecido"], expected_provenance(args));
  const std::string md = testing::slurp(dir / "out" / "report.md");
  EXPECT_EQ(md.rfind("# tecido report\n\ntecido " + std::string(io::tecido_version()) + ", commit " + io::tecido_commit() +
                         ": `" + io::shell_line({TECIDO_CLI}) + " " + args + "`\n\n",
                     0),
            0u)
      << md.substr(0, 400);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
