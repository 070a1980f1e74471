// Bad input for the pairs, cases and tolerance readers: exit 2 (CLI) or io::InputError with the
// file, the JSON pointer and the problem.
#include "tests/support/cli_runner.h"
#include "comparisons/io/plane_cases.h"
#include "comparisons/io/tri_pairs.h"
#include "comparisons/suites/suite.h"

#include <gtest/gtest.h>

#include <random>

namespace tecido {
namespace {

struct Bad {
  const char* name;
  const char* text;
  const char* where;
  const char* problem;
};

template <class F>
void expect_all_rejected(const std::vector<Bad>& bad, F read) {
  for (const Bad& b : bad) {
    try {
      read(io::parse_json_text(b.text, b.name), b.name);
      ADD_FAILURE() << b.name << ": accepted";
    } catch (const io::InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(std::string(b.name) + ": ", 0), 0u) << msg;
      if (*b.where) {
        EXPECT_NE(msg.find(std::string(": ") + b.where + ":"), std::string::npos) << b.name << ": " << msg;
      }
      EXPECT_NE(msg.find(b.problem), std::string::npos) << b.name << ": " << msg;
    }
  }
}

const char* kTri = "[[0,0,0],[1,0,0],[0,1,0]]";

TEST(PairsReader, RejectsBadPairs) {
  const std::string t = kTri;
  const std::vector<std::string> texts = {
      R"({"pair":[]})",
      R"({"pairs":{}})",
      R"({"pairs":[{"id":"a","a":)" + t + "}]}",
      R"({"pairs":[{"id":"a","a":[[0,0,0],[1,0,0]],"b":)" + t + "}]}",
      R"({"pairs":[{"id":"a","a":[[0,0,0],[1,0,0],[0,1]],"b":)" + t + "}]}",
      R"({"pairs":[{"id":"a","a":[[0,0,0],[1,0,0],[0,"1",0]],"b":)" + t + "}]}",
      R"({"pairs":[{"id":"a","a":[[0,0,0],[1,0,0],[0,1e400,0]],"b":)" + t + "}]}",
      R"({"pairs":[{"id":"a","a":[[0,0,0],[1,0,0],[0,1e16,0]],"b":)" + t + "}]}",
      R"({"pairs":[7]})",
  };
  static std::vector<std::string> keep;
  keep = texts;
  const std::vector<Bad> bad = {
      {"p1.json", keep[0].c_str(), "/pairs", "missing required key"},
      {"p2.json", keep[1].c_str(), "/pairs", "expected an array"},
      {"p3.json", keep[2].c_str(), "/pairs/0/b", "missing required key"},
      {"p4.json", keep[3].c_str(), "/pairs/0/a", "3 points"},
      {"p5.json", keep[4].c_str(), "/pairs/0/a/2", "3 numbers"},
      {"p6.json", keep[5].c_str(), "/pairs/0/a/2/1", "expected a number"},
      {"p7.json", keep[6].c_str(), "/pairs/0/a/2/1", "not finite"},
      {"p8.json", keep[7].c_str(), "/pairs/0/a/2/1", "out of range"},
      {"p9.json", keep[8].c_str(), "/pairs/0", "expected an object"},
  };
  expect_all_rejected(bad, [](const io::Json& j, const std::string& f) { return io::tri_pairs_from_json(j, f); });
}

TEST(PairsReader, IgnoresUnknownKeysAndRoundTrips) {
  const auto pairs = io::tri_pairs_from_json(
      io::parse_json_text(R"({"pairs":[{"id":"x","label":"coplanar","a":[[0,0,0],[1,0,0],[0,1,0]],"b":[[0.1,0.1,0],[2,0,0],[0,2,0]]}]})", "f"), "f");
  ASSERT_EQ(pairs.size(), 1u);
  const auto again = io::tri_pairs_from_json(io::parse_json_text(io::tri_pairs_to_json(pairs).dump(), "g"), "g");
  EXPECT_EQ(again[0].a[1], pairs[0].a[1]);
  EXPECT_EQ(again[0].b[0], pairs[0].b[0]);
}

TEST(CasesReader, RejectsBadCases) {
  const std::vector<Bad> bad = {
      {"c1.json", R"({"cases":[{"id":"a","plane":{"position":[0,0,0],"normal":[0,0,0],"forward":[1,0,0],"half_extents":[1,1]},"from":[0,0,1],"to":[0,0,-1]}]})",
       "/cases/0/plane/normal", "must not be zero"},
      {"c2.json", R"({"cases":[{"id":"a","plane":{"position":[0,0,0],"normal":[0,0,1],"forward":[0,0,2],"half_extents":[1,1]},"from":[0,0,1],"to":[0,0,-1]}]})",
       "/cases/0/plane/forward", "parallel"},
      {"c3.json", R"({"cases":[{"id":"a","plane":{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[-1,1]},"from":[0,0,1],"to":[0,0,-1]}]})",
       "/cases/0/plane/half_extents/0", ">= 0"},
      {"c4.json", R"({"cases":[{"id":"a","plane":{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[1,1]},"to":[0,0,-1]}]})",
       "/cases/0/from", "missing required key"},
      {"c5.json", R"({"cases":[{"id":"a","from":[0,0,1],"to":[0,0,-1]}]})", "/cases/0/plane", "missing required key"},
      {"c6.json", R"({"cases":"none"})", "/cases", "expected an array"},
      {"c7.json", R"([1,2,3])", "/", "expected an object"},
  };
  expect_all_rejected(bad, [](const io::Json& j, const std::string& f) { return io::plane_cases_from_json(j, f); });
}

// A plane written by plane_cases_to_json and read back is the same plane bit for bit, even when
// its forward was given nearly parallel to its normal: a case file reproduces what the suite saw.
TEST(CasesReader, WrittenPlanesReadBackBitForBit) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<io::PlaneCase> cases;
  for (int k = 0; k < 500; ++k) {
    io::PlaneCase c;
    c.id = "case-" + std::to_string(k);
    const Vec3 n(u(rng), u(rng), u(rng));
    const Vec3 f = k % 2 ? Vec3(n * 2.0 + Vec3(u(rng), u(rng), u(rng)) * 1e-7) : Vec3(u(rng), u(rng), u(rng));
    c.plane = make_bounded_plane(Vec3(u(rng), u(rng), u(rng)), n, f, Vec2(std::abs(u(rng)), std::abs(u(rng))), 0.25);
    c.from = Vec3(u(rng), u(rng), u(rng));
    c.to = Vec3(u(rng), u(rng), u(rng));
    cases.push_back(c);
  }
  const std::string text = io::plane_cases_to_json(cases).dump();
  const auto back = io::plane_cases_from_json(io::parse_json_text(text, "cases.json"), "cases.json");
  ASSERT_EQ(back.size(), cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    EXPECT_EQ(back[k].plane.normal, cases[k].plane.normal) << k;
    EXPECT_EQ(back[k].plane.forward, cases[k].plane.forward) << k;
    EXPECT_EQ(back[k].plane.position, cases[k].plane.position) << k;
    EXPECT_EQ(back[k].plane.half_extents, cases[k].plane.half_extents) << k;
    EXPECT_EQ(back[k].from, cases[k].from) << k;
    EXPECT_EQ(back[k].to, cases[k].to) << k;
  }
}

TEST(ToleranceFile, RejectsBadFilesAndMissingKeys) {
  const auto dir = testing::temp_dir("tolerances");
  testing::write_text(dir / "t1.json", R"({"order":{"band":"wide"}})");
  testing::write_text(dir / "t2.json", R"({"order":5})");
  testing::write_text(dir / "t3.json", R"({"order":{"band":0.15,"band":0.2}})");
  for (const char* f : {"t1.json", "t2.json", "t3.json"}) {
    EXPECT_THROW(suites::Tolerances::load((dir / f).string()), io::InputError) << f;
  }
  testing::write_text(dir / "t4.json", R"({"order":{"band":0.15}})");
  const auto t = suites::Tolerances::load((dir / "t4.json").string());
  EXPECT_EQ(t.get("/order/band"), 0.15);
  // Pointers that do not fit the document's shape are missing tolerances too, not crashes.
  const suites::Tolerances arr(io::parse_json_text("[1, [2]]", "arr.json"), "arr.json");
  for (const char* bad : {"/", "//", "/1/", "/order", "/1/x", "/7", "no-slash"}) EXPECT_THROW(arr.get(bad), io::InputError) << bad;
  EXPECT_EQ(arr.get("/1/0"), 2.0);
  try {
    t.get("/order/roundoff_floor");
    ADD_FAILURE();
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/order/roundoff_floor: missing tolerance"), std::string::npos) << e.what();
  }
  // The CLI: a tolerance file missing a key the suite needs is bad input, exit 2, no report.
  testing::write_text(dir / "t5.json", R"({"order":{"bandwidth":0.15}})");
  const auto r = testing::run_cli("suite order --tolerances '" + (dir / "t5.json").string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("missing tolerance"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "report.json"));
  std::filesystem::remove_all(dir);
}

TEST(TritriCli, PairsFileContractAndBadInput) {
  const auto dir = testing::temp_dir("tritri");
  testing::write_text(dir / "pairs.json", R"({"pairs":[
    {"id":"cross","a":[[0,0,0],[1,0,0],[0,1,0]],"b":[[0.2,0.2,-1],[0.2,0.2,1],[0.3,0.9,0.5]]},
    {"id":"apart","a":[[0,0,0],[1,0,0],[0,1,0]],"b":[[0,0,2],[1,0,2],[0,1,2]]}]})");
  auto r = testing::run_cli("tritri --pairs '" + (dir / "pairs.json").string() + "' --engines core --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["results"][0]["id"], "cross");
  EXPECT_EQ(j["results"][0]["core"], true);
  EXPECT_EQ(j["results"][1]["core"], false);
  r = testing::run_cli("tritri --pairs '" + (dir / "pairs.json").string() + "' --engines core,nope --json");
  EXPECT_EQ(r.code, 2);
  testing::write_text(dir / "bad.json", R"({"pairs":[{"id":"x","a":[[0,0,0],[1,0,0]],"b":[[0,0,0],[1,0,0],[0,1,0]]}]})");
  r = testing::run_cli("tritri --pairs '" + (dir / "bad.json").string() + "' --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/pairs/0/a"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
