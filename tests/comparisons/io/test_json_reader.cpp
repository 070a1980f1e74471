// The strict JSON reader every input goes through (comparisons/io/json_reader.h): nesting past
// io::kMaxJsonDepth is rejected while parsing, at the first level past the limit, with that
// level's pointer; duplicate keys at any depth; and through every command that reads JSON.
#include "tests/support/rejection.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/io/limits.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

using testing::expect_rejected;
using testing::run_cli;

std::string nested_arrays(std::size_t depth, const std::string& inner = "") {
  return std::string(depth, '[') + inner + std::string(depth, ']');
}

std::string repeat(const std::string& s, std::size_t n) {
  std::string out;
  out.reserve(s.size() * n);
  for (std::size_t k = 0; k < n; ++k) out += s;
  return out;
}

TEST(JsonReader, NestingAtTheLimitIsAcceptedOneMoreIsRejectedAtThatLevel) {
  const auto depth = static_cast<std::size_t>(io::kMaxJsonDepth);
  const io::Json ok = io::parse_json_text(nested_arrays(depth, "7"), "ok.json");
  const io::Json* deepest = &ok;
  for (std::size_t k = 0; k < depth; ++k) deepest = &(*deepest)[0];
  EXPECT_EQ(*deepest, 7);
  try {
    io::parse_json_text(nested_arrays(depth + 1), "deep.json");
    ADD_FAILURE() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where(), repeat("/0", depth));  // the first level past the limit
    EXPECT_EQ(e.problem(), "nesting deeper than 256 levels (the limit)");
  }
}

// The bomb of the issue: 200,000 levels. Rejected at level 257, so what the reader keeps is
// bounded by the limit, not by the bomb (the pointer in the message has exactly 256 steps).
TEST(JsonReader, NestingBombIsRejectedAtTheFirstLevelPastTheLimit) {
  for (const std::string& bomb : {nested_arrays(200000), repeat("{\"a\":", 200000) + "1" + std::string(200000, '}'),
                                  "{\"pairs\":[{\"id\":" + nested_arrays(100000) + "}]}"}) {
    try {
      io::parse_json_text(bomb, "bomb.json");
      ADD_FAILURE() << "accepted";
    } catch (const io::InputError& e) {
      EXPECT_EQ(std::count(e.where().begin(), e.where().end(), '/'), io::kMaxJsonDepth) << e.where().substr(0, 40);
      EXPECT_NE(e.problem().find("nesting deeper than 256 levels"), std::string::npos) << e.problem();
    }
  }
}

TEST(JsonReader, DuplicateKeysAreRejectedAtAnyDepthWithTheObjectsPointer) {
  try {
    io::parse_json_text(R"({"a":[{"x":1},{"y":{"k":1,"m":2,"k":3}}]})", "dup.json");
    ADD_FAILURE() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where(), "/a/1/y");
    EXPECT_EQ(e.problem(), "duplicate key \"k\"");
  }
  // The same key in different objects is fine; an object of many keys is read whole.
  std::string many = "{";
  for (int k = 0; k < 100000; ++k) many += (k ? ",\"" : "\"") + std::to_string(k) + "\":{\"k\":" + std::to_string(k) + "}";
  const io::Json j = io::parse_json_text(many + "}", "many.json");
  EXPECT_EQ(j.size(), 100000u);
  EXPECT_EQ(j["99999"]["k"], 99999);
}

// A syntax error names its line and column, never a JSON pointer (the value there does not exist).
TEST(JsonReader, SyntaxErrorsNameTheLineAndColumnOnly) {
  try {
    // Line 3 is `  "steps": }`: the parser stops at its 12th character, the '}'.
    io::parse_json_text("{\n  \"dt\": 0.01,\n  \"steps\": }\n", "bad.json");
    ADD_FAILURE() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where(), "line 3, column 12");
    EXPECT_EQ(e.problem().rfind("not valid JSON: syntax error while parsing value", 0), 0u) << e.problem();
    EXPECT_EQ(std::string(e.what()).rfind("bad.json: line 3, column 12: not valid JSON: ", 0), 0u) << e.what();
    EXPECT_EQ(std::string(e.what()).find("/steps"), std::string::npos) << e.what();
  }
  try {
    io::parse_json_text(R"({"a":[1,2,{"b":tru}]})", "bad.json");  // "tru}" ends at the 19th character
    ADD_FAILURE() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where(), "line 1, column 19");
    EXPECT_NE(e.problem().find("invalid literal"), std::string::npos) << e.problem();
  }
}

// The CLI's line for a scene cut short: file, line and column, the problem; exit 2.
TEST(JsonReader, CliNamesTheLineAndColumnOfASyntaxError) {
  const auto dir = testing::temp_dir("syntax");
  const auto file = dir / "s.json";
  testing::write_text(file, "{\"dt\":0.01,\"steps\":}");
  expect_rejected(run_cli("run " + testing::quoted(file.string())),
                  {file.string() + ": line 1, column 20: not valid JSON: syntax error while parsing value"}, "syntax");
  std::filesystem::remove_all(dir);
}

// An unknown key names the keys allowed where it stands and the nearest of them.
TEST(JsonReader, UnknownKeyListsTheAllowedKeysAndTheNearest) {
  EXPECT_EQ(io::unknown_key_problem("stiffness", {"rows", "stiffness_b", "stiffness_a", "pins"}),
            "unknown key \"stiffness\" (allowed: rows, stiffness_b, stiffness_a, pins; did you mean \"stiffness_b\" or "
            "\"stiffness_a\"?); keys starting with '_' are comments");
  EXPECT_EQ(io::unknown_key_problem("gibberish", {"dt", "steps"}),
            "unknown key \"gibberish\" (allowed: dt, steps); keys starting with '_' are comments");
  const io::JsonReader r("k.json");
  const io::Json obj = io::Json::parse(R"({"_note":"a comment","dt":1,"stpes":2})");
  try {
    r.only_keys(obj, "/x", {"dt", "steps"});
    ADD_FAILURE() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "k.json: /x/stpes: unknown key \"stpes\" (allowed: dt, steps; did you mean \"steps\"?); keys starting "
              "with '_' are comments");
  }
  EXPECT_NO_THROW(r.only_keys(io::Json::parse(R"({"_anything":1,"dt":1})"), "/x", {"dt", "steps"}));
}

// Every command that reads JSON rejects the bomb with its one line, exit 2, and writes nothing.
TEST(JsonReader, EveryJsonInputOfTheCliRejectsTheNestingBomb) {
  const auto dir = testing::temp_dir("bomb");
  const auto bomb = dir / "bomb.json";
  testing::write_text(bomb, nested_arrays(200000));
  const std::string b = "'" + bomb.string() + "'", out = "'" + (dir / "out").string() + "'";
  const std::vector<std::string> commands = {
      "run " + b + " --out " + out,
      "tritri --pairs " + b + " --json",
      "plane --cases " + b + " --json",
      "suite order --tolerances " + b + " --out " + out,
      "experiment self-contact --quick --runs 0 --scene " + b + " --out " + out,
      "experiment self-contact --quick --runs 0 --seed-table " + b + " --out " + out,
      "merge " + b + " --out " + out,
  };
  for (const auto& c : commands) {
    const auto r = run_cli(c);
    expect_rejected(r, {bomb.string() + ": /0/0/0/", "nesting deeper than 256 levels (the limit)"}, c);
    EXPECT_FALSE(std::filesystem::exists(dir / "out")) << c;
  }
  std::filesystem::remove_all(dir);
}

// Memory, asserted structurally: the 400 KB bomb that grew past 20 GB is rejected by a CLI held
// to 256 MB of address space (ulimit -v), so the reader cannot have needed more.
TEST(JsonReader, NestingBombFitsIn256MegabytesOfAddressSpace) {
#ifdef TECIDO_SANITIZED
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space; ulimit -v does not apply";
#endif
  const auto dir = testing::temp_dir("bomb-memory");
  testing::write_text(dir / "bomb.json", nested_arrays(200000));
  const auto r = testing::run_cli_with("ulimit -v 262144", "run '" + (dir / "bomb.json").string() + "' --json");
  expect_rejected(r, {"nesting deeper than 256 levels"}, "bomb under ulimit -v");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
