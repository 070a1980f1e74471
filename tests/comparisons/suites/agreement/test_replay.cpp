// The agreement kit's replay (comparisons/suites/agreement/replay.*, with the door options of
// comparisons/engines/outside/door_option.*) on worked examples: a disagreement's labels carry the
// engine, both answers and the truth; per engine, misses and false hits are counted and the first
// ids kept; the replay command names the file, the engine twice (--engines, --of-engine) and its
// door, quoted for a shell; stderr lines skip the engines that agree and say when the file's cap
// cut an engine's entries.
#include "comparisons/engines/outside/door_option.h"
#include "comparisons/suites/agreement/replay.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace tecido::suites::agreement {
namespace {

TEST(AgreementReplay, LabelsNameTheEngineBothAnswersAndTheTruth) {
  const Disagreement miss{1, 0, 7, {false, 0.0}, {true, 0.25}};
  const io::Json j = disagreement_labels("naive", miss, "toi");
  EXPECT_EQ(j["engine"], "naive");
  EXPECT_EQ(j["answer"], io::Json::parse(R"({"hit":false,"toi":null})"));
  EXPECT_EQ(j["referee"], io::Json::parse(R"({"hit":true,"toi":0.25})"));
  EXPECT_EQ(j["truth"], true);
  const io::Json no_time = disagreement_labels("mt", {0, 0, 1, {true, 0.0}, {false, 0.0}}, nullptr);
  EXPECT_EQ(no_time["answer"], io::Json::parse(R"({"hit":true})"));
  EXPECT_EQ(no_time["truth"], false);

  io::Json doc = {{"pairs", {{{"id", "a:random/7"}}, {{"id", "b:random/1"}}}}};
  label_entries(doc, "pairs", {"a", "b"}, {{0, 0, 7, {false, 0.0}, {true, 0.0}}, {1, 0, 1, {true, 0.0}, {false, 0.0}}},
                nullptr);
  EXPECT_EQ(doc["pairs"][0]["id"], "a:random/7");
  EXPECT_EQ(doc["pairs"][0]["engine"], "a");
  EXPECT_EQ(doc["pairs"][1]["engine"], "b");
  EXPECT_EQ(doc["pairs"][1]["truth"], false);
}

TEST(AgreementReplay, CountsPerEngineAndKeepsTheFirstIds) {
  std::vector<std::size_t> kept_engine;
  std::vector<std::string> ids;
  for (int k = 0; k < 7; ++k) kept_engine.push_back(1), ids.push_back("b:f/" + std::to_string(k));
  const auto d = engine_disagreements({"a", "b"}, {"", "--plugin /x.so"}, {0, 4}, {0, 3}, kept_engine, ids);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].found(), 0);
  EXPECT_EQ(d[1].misses, 4);
  EXPECT_EQ(d[1].false_hits, 3);
  EXPECT_EQ(d[1].kept, 7);
  ASSERT_EQ(d[1].first_ids.size(), kFirstIds);
  EXPECT_EQ(d[1].first_ids[0], "b:f/0");
  EXPECT_EQ(d[1].first_ids[4], "b:f/4");
}

TEST(AgreementReplay, CommandCarriesTheFileTheEngineAndItsDoor) {
  EngineDisagreements e{"naive", "--engine-cmd 'naive=python3 naive.py'", 2, 1, 3, {"naive:x/1"}};
  EXPECT_EQ(replay_command({"tecido ccd", "--queries"}, "/out dir/ccd/disagreements.json", e),
            "tecido ccd --queries '/out dir/ccd/disagreements.json' --engines naive --of-engine naive "
            "--engine-cmd 'naive=python3 naive.py' --json");
  e.door_option.clear();
  EXPECT_EQ(replay_command({"tecido tritri", "--pairs"}, "DIR/tritri/disagreements.json", e),
            "tecido tritri --pairs DIR/tritri/disagreements.json --engines naive --of-engine naive --json");
}

TEST(AgreementReplay, StderrLinesSkipAgreeingEnginesAndSayWhenCut) {
  const std::vector<EngineDisagreements> engines = {
      {"core", "", 0, 0, 0, {}},
      {"mt", "", 5, 0, 5, {"mt:random/1", "mt:random/4"}},
      {"fcl", "", 3, 4, 2, {"fcl:random/2", "fcl:edge/9"}},
  };
  const auto lines = stderr_lines("tritri", {"tecido tritri", "--pairs"}, "/o/tritri/disagreements.json", engines);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0],
            "tritri: mt: 5 misses (false negatives), 0 false hits (false positives); first: mt:random/1, "
            "mt:random/4, ...; all in /o/tritri/disagreements.json; replay: tecido tritri --pairs "
            "/o/tritri/disagreements.json --engines mt --of-engine mt --json");
  EXPECT_NE(lines[1].find("2 of them in /o/tritri/disagreements.json (the file's cap)"), std::string::npos) << lines[1];
  const std::string md = replay_markdown({"tecido tritri", "--pairs"}, "DIR/tritri/disagreements.json", engines);
  EXPECT_EQ(md.find("`core`"), std::string::npos);
  EXPECT_NE(md.find("- `mt`: 5 misses"), std::string::npos) << md;
}

TEST(AgreementReplay, DoorOptionsAreShellWords) {
  EXPECT_EQ(outside::shell_word("naive"), "naive");
  EXPECT_EQ(outside::shell_word("a b"), "'a b'");
  EXPECT_EQ(outside::shell_word("it's"), "'it'\\''s'");
  EXPECT_EQ(outside::shell_word(""), "''");
  EXPECT_EQ(outside::engine_cmd_option("py", "python3 e.py"), "--engine-cmd 'py=python3 e.py'");
  const std::string abs = (std::filesystem::current_path() / "lib" / "x.so").string();
  EXPECT_EQ(outside::plugin_option("lib/./x.so"), "--plugin " + outside::shell_word(abs));
}

}  // namespace
}  // namespace tecido::suites::agreement
