// Ids of the entries of pairs and cases files (comparisons/io/entry_id.h): results are keyed by
// id, so a second entry with an id already used is rejected at its pointer, naming the first.
#include "tests/support/rejection.h"
#include "comparisons/io/plane_cases.h"
#include "comparisons/io/tri_pairs.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

const char* kTri = R"("a":[[0,0,0],[1,0,0],[0,1,0]],"b":[[0,0,1],[1,0,1],[0,1,1]])";
const char* kCase =
    R"("plane":{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[1,1]},"from":[0,0,1],"to":[0,0,-1])";

/// {"<list>":[{<id_0>,<body>}, ...]} with the given "id" members ("" = no id).
std::string file_with(const std::string& list, const std::vector<std::string>& ids, const char* body) {
  std::string s = "{\"" + list + "\":[";
  for (std::size_t k = 0; k < ids.size(); ++k)
    s += std::string(k ? "," : "") + "{" + (ids[k].empty() ? "" : "\"id\":" + ids[k] + ",") + body + "}";
  return s + "]}";
}

std::string rejection(const std::string& list, const std::vector<std::string>& ids) {
  try {
    const std::string text = file_with(list, ids, list == "pairs" ? kTri : kCase);
    if (list == "pairs") io::tri_pairs_from_json(io::parse_json_text(text, "f.json"), "f.json");
    else io::plane_cases_from_json(io::parse_json_text(text, "f.json"), "f.json");
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(EntryId, SecondUseOfAnIdIsRejectedNamingTheFirst) {
  const std::vector<std::string> ids = {"\"x\"", "\"y\"", "\"a\"", "\"b\"", "\"c\"", "\"d\"", "\"e\"", "\"a\""};
  EXPECT_EQ(rejection("pairs", ids), "f.json: /pairs/7/id: duplicate id \"a\" (first at /pairs/2/id)");
  EXPECT_EQ(rejection("cases", ids), "f.json: /cases/7/id: duplicate id \"a\" (first at /cases/2/id)");
}

// Ids are compared as the output prints them: a number 1 and a string "1" are one id, and an
// entry without id is known by its index.
TEST(EntryId, NumbersAndImplicitIdsCollideAsTheyWouldInTheOutput) {
  EXPECT_EQ(rejection("pairs", {"1", "\"1\""}), "f.json: /pairs/1/id: duplicate id \"1\" (first at /pairs/0/id)");
  EXPECT_EQ(rejection("cases", {"\"1\"", ""}),
            "f.json: /cases/1: duplicate id \"1\" (first at /cases/0/id) (an entry without \"id\" is known by its index)");
  EXPECT_EQ(rejection("pairs", {"", "", "\"a\""}), "accepted");
  EXPECT_EQ(rejection("pairs", {"[1,2]", "[1, 2]"}), "f.json: /pairs/1/id: duplicate id \"[1,2]\" (first at /pairs/0/id)");
}

TEST(EntryId, TritriAndPlaneExitTwoWithTheSecondEntrysPointer) {
  const auto dir = testing::temp_dir("dup-ids");
  testing::write_text(dir / "pairs.json", file_with("pairs", {"\"a\"", "\"b\"", "\"a\""}, kTri));
  testing::write_text(dir / "cases.json", file_with("cases", {"\"p\"", "\"p\""}, kCase));
  const std::string pairs = (dir / "pairs.json").string(), cases = (dir / "cases.json").string();
  testing::expect_rejected(testing::run_cli("tritri --pairs '" + pairs + "' --engines core --json"),
                           {pairs + ": /pairs/2/id: duplicate id \"a\" (first at /pairs/0/id)"}, "tritri");
  testing::expect_rejected(testing::run_cli("plane --cases '" + cases + "' --engines core --json"),
                           {cases + ": /cases/1/id: duplicate id \"p\" (first at /cases/0/id)"}, "plane");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
