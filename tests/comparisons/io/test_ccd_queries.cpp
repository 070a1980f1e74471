// The queries files of `tecido ccd` (comparisons/io/ccd_queries.h): the JSON reader and writer
// (read back bit for bit) and the CCD benchmark's CSV reader, with their bad input.
#include "comparisons/io/ccd_queries.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace tecido {
namespace {

std::string query_json(const std::string& id, const std::string& kind, const std::string& t0 = "",
                       const std::string& t1 = "") {
  const std::string pts = "[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]";
  return R"({"id":)" + id + R"(,"kind":")" + kind + R"(","t0":)" + (t0.empty() ? pts : t0) + R"(,"t1":)" +
         (t1.empty() ? pts : t1) + "}";
}

/// The message of the InputError reading `text` throws ("" when it is accepted).
std::string json_error(const std::string& text) {
  try {
    io::ccd_queries_from_json(io::parse_json_text(text, "q.json"), "q.json");
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

std::string csv_error(const std::string& text) {
  try {
    io::parse_ccd_queries_csv(text, "q.csv", CcdKind::EdgeEdge);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CcdQueriesJson, ReadsEveryField) {
  const std::string text = R"({"queries":[)" + query_json(R"("a")", "vertex-face") + "," +
                           query_json("7", "edge-edge", "[[1,2,3],[4,5,6],[7,8,9],[10,11,12]]") + R"(,)" +
                           R"({"kind":"edge-edge","truth":true,"label":"x","t0":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]],)" +
                           R"("t1":[[0,0,0],[1,0,0],[0,1,0],[0,0,-1.5]]}]})";
  const auto q = io::ccd_queries_from_json(io::parse_json_text(text, "q.json"), "q.json");
  ASSERT_EQ(q.size(), 3u);
  EXPECT_EQ(q[0].id, "a");
  EXPECT_EQ(q[0].query.kind, CcdKind::VertexFace);
  EXPECT_EQ(q[1].id, "7");  // a non-string id is its JSON text
  EXPECT_EQ(q[1].query.kind, CcdKind::EdgeEdge);
  EXPECT_EQ(q[1].query.x0[3], Vec3(10, 11, 12));
  EXPECT_EQ(q[2].id, "2");  // an absent id is the index
  EXPECT_EQ(q[2].query.x1[3], Vec3(0, 0, -1.5));
  EXPECT_FALSE(q[0].truth.has_value());
  ASSERT_TRUE(q[2].truth.has_value());
  EXPECT_TRUE(*q[2].truth);
  EXPECT_FALSE(q[0].rational.has_value());
}

TEST(CcdQueriesJson, WriterRoundTripsBitForBit) {
  std::mt19937_64 rng(11);
  std::vector<io::CcdQueryEntry> entries;
  const double specials[] = {-0.0, 0.0, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::min(), 0.1, 1.0 / 3.0, 1e300, 123456789012345680.0};
  std::size_t s = 0;
  for (int k = 0; k < 200; ++k) {
    io::CcdQueryEntry e;
    e.id = "q" + std::to_string(k);
    e.query.kind = k % 2 ? CcdKind::EdgeEdge : CcdKind::VertexFace;
    if (k % 3 == 0) e.truth = k % 2 == 0;
    for (auto* frame : {&e.query.x0, &e.query.x1})
      for (Vec3& p : *frame)
        for (int a = 0; a < 3; ++a) {
          double x;
          do {  // random bit patterns: every exponent, subnormals, both signs
            const std::uint64_t bits = rng();
            std::memcpy(&x, &bits, sizeof x);
          } while (!std::isfinite(x));
          p[a] = (k < 20) ? specials[s++ % std::size(specials)] : x;
        }
    entries.push_back(e);
  }
  const std::string text = io::ccd_queries_to_json(entries).dump();
  const auto back = io::ccd_queries_from_json(io::parse_json_text(text, "w.json"), "w.json");
  ASSERT_EQ(back.size(), entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    EXPECT_EQ(back[k].id, entries[k].id);
    EXPECT_EQ(back[k].query.kind, entries[k].query.kind);
    EXPECT_EQ(back[k].truth, entries[k].truth);
    EXPECT_EQ(std::memcmp(back[k].query.x0.data(), entries[k].query.x0.data(), sizeof(entries[k].query.x0)), 0) << k;
    EXPECT_EQ(std::memcmp(back[k].query.x1.data(), entries[k].query.x1.data(), sizeof(entries[k].query.x1)), 0) << k;
  }
}

TEST(CcdQueriesJson, RejectsBadInputNamingThePointer) {
  const std::string ok = query_json(R"("a")", "vertex-face");
  struct Bad {
    std::string text, where, problem;
  };
  const std::vector<Bad> bad = {
      {R"({"query":[]})", "/queries", "missing required key"},
      {R"({"queries":{}})", "/queries", "expected an array"},
      {R"({"queries":[3]})", "/queries/0", "expected an object"},
      {R"({"queries":[)" + ok + "," + ok + "]}", "/queries/1/id", "duplicate id \"a\" (first at /queries/0/id)"},
      {R"({"queries":[)" + ok + ",{\"id\":\"0\"," + ok.substr(10) + "]}", "", ""},  // accepted: ids differ
      {R"({"queries":[)" + query_json("1", "face-vertex") + "]}", "/queries/0/kind", "unknown kind"},
      {R"({"queries":[)" + query_json("1", "edge-edge", "[[0,0,0],[1,0,0],[0,1,0]]") + "]}", "/queries/0/t0",
       "4 points"},
      {R"({"queries":[)" + query_json("1", "edge-edge", "", "[[0,0,0],[1,0,0],[0,1,0],[0,0]]") + "]}",
       "/queries/0/t1/3", "3 numbers"},
      {R"({"queries":[)" + query_json("1", "edge-edge", "[[0,0,0],[1,0,0],[0,\"1\",0],[0,0,1]]") + "]}",
       "/queries/0/t0/2/1", "expected a number"},
      {R"({"queries":[)" + query_json("1", "edge-edge", "[[0,0,0],[1,0,0],[0,1e400,0],[0,0,1]]") + "]}",
       "/queries/0/t0/2/1", "not finite"},
      {R"({"queries":[{"kind":"edge-edge","t0":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}]})", "/queries/0/t1",
       "missing required key"},
      {R"({"queries":[{"id":"x","kind":"edge-edge","truth":1,"t0":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]],)"
       R"("t1":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]}]})",
       "/queries/0/truth", "expected true or false"},
  };
  for (const Bad& b : bad) {
    const std::string msg = json_error(b.text);
    if (b.where.empty()) {
      EXPECT_EQ(msg, "") << b.text;
      continue;
    }
    EXPECT_EQ(msg.rfind("q.json: " + b.where + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find(b.problem), std::string::npos) << msg;
  }
}

TEST(CcdQueriesJson, DuplicateIdOfAnAbsentIdNamesTheEntry) {
  // The second entry has no id, so its id is its index "1", which the first entry already took.
  const std::string text = R"({"queries":[)" + query_json(R"("1")", "edge-edge") + "," +
                           query_json(R"("x")", "edge-edge").replace(0, 10, "{") + "]}";
  EXPECT_EQ(json_error(text).rfind("q.json: /queries/1: duplicate id \"1\" (first at /queries/0/id)", 0), 0u)
      << json_error(text);
}

/// A CSV query of 8 rows: row r has x = r/den, y = -r, z = 0 (as text), the truth column `truth`.
std::string csv_query(int truth, const std::string& den = "4") {
  std::string s;
  for (int r = 0; r < 8; ++r) s += std::to_string(r) + "," + den + ",-" + std::to_string(r) + ",1,0,1," + std::to_string(truth) + "\n";
  return s;
}

TEST(CcdQueriesCsv, ReadsRationalsAsTextInTheJsonOrder) {
  const std::string big = "123456789012345678901234567890";
  std::string text = csv_query(1) + "\n" + csv_query(0, "8");
  text += big + ",-" + big + "0, 3 ,1,0,1,1\r\n";
  for (int r = 1; r < 8; ++r) text += "0,1,0,1,0,1,1\r\n";
  const auto q = io::parse_ccd_queries_csv(text, "q.csv", CcdKind::VertexFace);
  ASSERT_EQ(q.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(q[k].id, std::to_string(k));
    ASSERT_TRUE(q[k].rational.has_value());
    EXPECT_EQ(q[k].rational->kind, CcdKind::VertexFace);
    EXPECT_EQ(q[k].query.kind, CcdKind::VertexFace);
  }
  EXPECT_TRUE(*q[0].truth);
  EXPECT_FALSE(*q[1].truth);
  // Row r of a query: r < 4 is x0[r], otherwise x1[r - 4].
  EXPECT_EQ(q[0].rational->x0[2][0].num, "2");
  EXPECT_EQ(q[0].rational->x0[2][0].den, "4");
  EXPECT_EQ(q[1].rational->x1[1][1].num, "-5");
  EXPECT_EQ(q[1].rational->x1[1][0].den, "8");
  EXPECT_EQ(q[2].rational->x0[0][0].num, big);
  EXPECT_EQ(q[2].rational->x0[0][0].den, "-" + big + "0");
  EXPECT_EQ(q[2].rational->x0[0][1].num, "3");  // spaces around a field are dropped
}

TEST(CcdQueriesCsv, RejectsBadInputNamingTheLine) {
  const std::string q = csv_query(0);
  std::string short_row = q;
  short_row.replace(short_row.find("2,4,-2,1,0,1,0"), 14, "2,4,-2,1,0,1");
  struct Bad {
    std::string text, where, problem;
  };
  const std::vector<Bad> bad = {
      {short_row, "line 3", "expected 7 columns"},
      {q + "1,2,3,4,5,6,0,8\n", "line 9", "got 8"},
      {q + "1,2,3,4.5,5,6,0\n", "line 9", "column 4 (y denominator): not an integer: \"4.5\""},
      {q + "1,2,3,4,x,6,0\n", "line 9", "column 5 (z numerator): not an integer"},
      {q + "1,2,3,4,,6,0\n", "line 9", "column 5 (z numerator): empty"},
      {q + "1,0,3,4,5,6,0\n", "line 9", "column 2 (x denominator): zero denominator"},
      {q + "1,2,3,4,5,-000,0\n", "line 9", "column 6 (z denominator): zero denominator"},
      {q + "1,2,3,4,5,6,2\n", "line 9", "column 7 (truth): expected 0 or 1, got \"2\""},
      {q + "1,2,3,4,5,6,-1\n", "line 9", "expected 0 or 1"},
      {q + "1,2,3,4,5,6,0\n1,2,3,4,5,6,1\n", "line 10", "truth 1 disagrees with the query's first row (line 9: 0)"},
      {q + "1,2,3,4,5,6,0\n\n1,2,3,4,5,6,0\n", "line 11", "10 rows is not a multiple of 8"},
      {q + "1," + std::string(io::kMaxCcdIntegerDigits + 1, '7') + ",3,4,5,6,0\n", "line 9", "digits"},
      {"\n\n", "/", "no query rows"},
  };
  for (const Bad& b : bad) {
    const std::string msg = csv_error(b.text);
    EXPECT_EQ(msg.rfind("q.csv: " + b.where + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find(b.problem), std::string::npos) << msg;
  }
  // The row-count message names the query's first line and the count.
  EXPECT_NE(csv_error(q + "1,2,3,4,5,6,0\n\n1,2,3,4,5,6,0\n").find("the query starting at line 9 has 2 rows"),
            std::string::npos);
}

}  // namespace
}  // namespace tecido
