// The query commands on the query-command scaffold (comparisons/cli/query_command.*): `tecido
// plane` and `tecido tritri` print exactly what they printed before the scaffold (the expected
// lines are the outputs of the commit before it, on the repository's sample inputs), `tecido ccd`
// keeps its own option between the input and --engines, and every one refuses an unknown engine
// with exit 2 and the same one-line message.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <string>

namespace tecido {
namespace {

using testing::run_cli;

std::string source(const std::string& path) { return "'" + std::string(TECIDO_SOURCE_DIR) + "/" + path + "'"; }

TEST(CliQueries, PlaneRowsAreUnchanged) {
  const auto r = run_cli("plane --cases " + source("data/fuzz/fuzz_plane_cases/valid_two.json") +
                         " --engines exact,core --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out,
            "{\"results\":[{\"core\":{\"hit\":true,\"t\":0.25},\"exact\":{\"hit\":true,\"t\":0.25},\"id\":\"through\"},"
            "{\"core\":{\"hit\":false,\"t\":null},\"exact\":{\"hit\":false,\"t\":null},\"id\":\"outside\"}]}\n");
  EXPECT_EQ(r.err, "");
}

TEST(CliQueries, TritriRowsAreUnchanged) {
  const auto r = run_cli("tritri --pairs " + source("data/fuzz/fuzz_tri_pairs/valid_crossing.json") +
                         " --engines exact,core-mt --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "{\"results\":[{\"core-mt\":true,\"exact\":true,\"id\":\"cross\"},{\"core-mt\":false,\"exact\":false,"
                   "\"id\":\"apart\"}]}\n");
}

TEST(CliQueries, EveryCommandRefusesAnUnknownEngine) {
  const auto plane = run_cli("plane --cases " + source("data/fuzz/fuzz_plane_cases/valid_two.json") + " --engines nope --json");
  EXPECT_EQ(plane.code, 2);
  EXPECT_EQ(plane.err, "tecido: --engines: unknown plane engine \"nope\" (known: core, core-seed, fcl, exact)\n");
  const auto tritri = run_cli("tritri --pairs " + source("examples/inputs/pairs.json") + " --engines nope --json");
  EXPECT_EQ(tritri.code, 2);
  EXPECT_NE(tritri.err.find("unknown tritri engine \"nope\""), std::string::npos) << tritri.err;
  const auto ccd = run_cli("ccd --queries " + source("examples/inputs/ccd_queries.json") + " --engines nope --json");
  EXPECT_EQ(ccd.code, 2);
  EXPECT_NE(ccd.err.find("unknown ccd engine \"nope\""), std::string::npos) << ccd.err;
}

TEST(CliQueries, HelpListsTheOptionsInTheirOrder) {
  const auto plane = run_cli("plane --help");
  const std::string& p = plane.out;
  ASSERT_NE(p.find("--cases TEXT REQUIRED"), std::string::npos) << p;
  EXPECT_LT(p.find("--cases"), p.find("--engines"));
  EXPECT_LT(p.find("--engines"), p.find("--json"));
  EXPECT_LT(p.find("--json"), p.find("--plugin"));
  EXPECT_NE(p.find("Comma-separated engines (core,core-seed,fcl,exact, and outside engines by name; default: every one)"),
            std::string::npos)
      << p;
  const auto ccd = run_cli("ccd --help");
  const std::string& c = ccd.out;
  EXPECT_LT(c.find("--queries"), c.find("--csv-kind"));
  EXPECT_LT(c.find("--csv-kind"), c.find("--engines"));
  EXPECT_NE(c.find("Output: {\"results\""), std::string::npos) << "the footer";
}

}  // namespace
}  // namespace tecido
