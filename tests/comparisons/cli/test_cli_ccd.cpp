// `tecido ccd` end to end: hand-worked queries through every engine, the CCD benchmark's CSV
// (truth, rounded rationals counted apart, the summary on stderr) and bad input (exit 2).
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace tecido {
namespace {

using testing::run_cli;
using testing::temp_dir;
using testing::write_text;
using Json = nlohmann::json;

// Hand-worked: the triangle (0,0,0), (1,0,0), (0,1,0) at rest; a vertex going from
// (1/8, 1/16, 1) to (3/8, 7/16, -1) crosses z = 0 at t = 1/2 at (1/4, 1/4), inside: a hit at 1/2
// (its motion is oblique: Bullet misses a vertex at rest along any of its 13 cull directions);
// falling straight down through (2, 2) it never touches.
// Edges: a = (0,0,0)-(1,0,0) at rest; b = (1/2,-1,z)-(1/2,1,z) falling from z = 1/4 to z = -3/4
// crosses a at (1/2, 0, 0) at t = 1/4.
const char* kQueries = R"({"queries":[
 {"id":"vf-hit","kind":"vertex-face","t0":[[0.125,0.0625,1],[0,0,0],[1,0,0],[0,1,0]],"t1":[[0.375,0.4375,-1],[0,0,0],[1,0,0],[0,1,0]]},
 {"id":"vf-miss","kind":"vertex-face","t0":[[2,2,1],[0,0,0],[1,0,0],[0,1,0]],"t1":[[2,2,-1],[0,0,0],[1,0,0],[0,1,0]]},
 {"id":"ee-hit","kind":"edge-edge","t0":[[0,0,0],[1,0,0],[0.5,-1,0.25],[0.5,1,0.25]],"t1":[[0,0,0],[1,0,0],[0.5,-1,-0.75],[0.5,1,-0.75]]}
]})";

TEST(CliCcd, AnswersHandWorkedQueriesPerEngine) {
  const auto dir = temp_dir("ccd-json");
  write_text(dir / "q.json", kQueries);
  const auto r = run_cli("ccd --queries '" + (dir / "q.json").string() + "' --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // no truth in the file: no summary
  const Json out = Json::parse(r.out);
  const Json& res = out.at("results");
  ASSERT_EQ(res.size(), 3u);
  EXPECT_EQ(res[0].at("id"), "vf-hit");
  EXPECT_FALSE(res[0].contains("truth"));
  for (const char* e : {"core", "exact", "fcl", "bullet"}) {
    ASSERT_TRUE(res[0].contains(e)) << e;
    EXPECT_TRUE(res[0][e].at("hit").get<bool>()) << e;
    EXPECT_NEAR(res[0][e].at("toi").get<double>(), 0.5, 1e-5) << e;
    EXPECT_FALSE(res[1][e].at("hit").get<bool>()) << e;
    EXPECT_TRUE(res[1][e].at("toi").is_null()) << e;
  }
  EXPECT_EQ(res[0]["exact"]["toi"].get<double>(), 0.5);  // exact: the exact time
  EXPECT_LE(res[0]["core"]["toi"].get<double>(), 0.5);   // core: never after it
  EXPECT_EQ(res[2]["exact"]["toi"].get<double>(), 0.25);
  EXPECT_LE(res[2]["core"]["toi"].get<double>(), 0.25);
  EXPECT_GE(res[2]["core"]["toi"].get<double>(), 0.25 - 0x1p-20);
  EXPECT_TRUE(res[2]["bullet"].is_null());  // Bullet has no edge-edge test
  // --engines picks and orders the engines.
  const auto two = run_cli("ccd --queries '" + (dir / "q.json").string() + "' --engines exact,core --json");
  ASSERT_EQ(two.code, 0) << two.err;
  const Json row = Json::parse(two.out)["results"][0];
  EXPECT_EQ(row.size(), 3u);
  EXPECT_FALSE(row.contains("fcl"));
}

/// The benchmark's CSV rows of one query: 8 points as "num,den" text, then the truth.
std::string csv_query(const std::vector<std::array<std::string, 3>>& pts, int truth) {
  std::string s;
  for (const auto& p : pts) s += p[0] + "," + p[1] + "," + p[2] + "," + std::to_string(truth) + "\n";
  return s;
}

TEST(CliCcd, ReadsTheBenchmarksCsvAndCountsRoundedQueriesApart) {
  const auto dir = temp_dir("ccd-csv");
  // Query 0 is the vertex-face hit above as rationals (1/8 is "1,8"); query 1 the same with the
  // vertex starting at x = 1/3 (not a double: rounded), still a hit; query 2 the miss, whose truth
  // column says 1 (a deliberately wrong truth, so every engine shows one false negative).
  const std::string h = "0,1", one = "1,1";
  auto q = [&](const std::string& x0, const std::string& y0, const std::string& x1, const std::string& y1) {
    return std::vector<std::array<std::string, 3>>{{x0, y0, one}, {h, h, h},       {one, h, h}, {h, one, h},
                                                   {x1, y1, "-1,1"}, {h, h, h},    {one, h, h}, {h, one, h}};
  };
  const std::string text = csv_query(q("1,8", "1,16", "3,8", "7,16"), 1) + csv_query(q("1,3", "1,16", "3,8", "7,16"), 1) +
                           csv_query(q("2,1", "2,1", "2,1", "2,1"), 1);
  write_text(dir / "vf.csv", text);
  const auto r = run_cli("ccd --queries '" + (dir / "vf.csv").string() + "' --csv-kind vertex-face --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const Json res = Json::parse(r.out).at("results");
  ASSERT_EQ(res.size(), 3u);
  EXPECT_EQ(res[0]["id"], "0");
  EXPECT_EQ(res[2]["id"], "2");
  EXPECT_EQ(res[0]["truth"], true);
  EXPECT_EQ(res[0]["rounded"], false);
  EXPECT_EQ(res[1]["rounded"], true);
  EXPECT_EQ(res[0]["exact"]["toi"].get<double>(), 0.5);
  EXPECT_TRUE(res[1]["exact"]["hit"].get<bool>());
  EXPECT_FALSE(res[2]["exact"]["hit"].get<bool>());
  // One summary line per engine; the rounded query is counted apart for the floating engines.
  EXPECT_NE(r.err.find("tecido ccd: exact: 0 false positives, 1 false negatives of 3 queries\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tecido ccd: core: 0 false positives, 1 false negatives of 2 queries; rounded queries apart: "
                       "0 false positives, 0 false negatives of 1"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("tecido ccd: fcl: "), std::string::npos);
}

TEST(CliCcd, BadInputExitsTwoWithOneLine) {
  const auto dir = temp_dir("ccd-bad");
  write_text(dir / "q.json", kQueries);
  write_text(dir / "short.csv", "1,2,3,4,5,6,0\n1,2,3,4,5\n");
  write_text(dir / "dup.json", R"({"queries":[{"id":"a","kind":"edge-edge","t0":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]],)"
                               R"("t1":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]},{"id":"a","kind":"edge-edge",)"
                               R"("t0":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]],"t1":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}]})");
  struct Case {
    std::string args, message;
  };
  const std::string d = dir.string();
  const std::vector<Case> cases = {
      {"ccd --queries '" + d + "/short.csv' --csv-kind edge-edge", d + "/short.csv: line 2: expected 7 columns"},
      {"ccd --queries '" + d + "/short.csv'", "a CSV file needs --csv-kind"},
      {"ccd --queries '" + d + "/q.json' --csv-kind face", "--csv-kind: expected vertex-face or edge-edge"},
      {"ccd --queries '" + d + "/q.json' --engines core,nope", "unknown ccd engine \"nope\""},
      {"ccd --queries '" + d + "/dup.json'", d + "/dup.json: /queries/1/id: duplicate id \"a\""},
      {"ccd --queries '" + d + "/missing.json'", d + "/missing.json"},
  };
  for (const Case& c : cases) {
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(r.out, "") << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace tecido
