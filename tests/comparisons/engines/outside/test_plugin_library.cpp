// Loading plug-ins: the example's table as written in examples/plugin; every way a library can fail
// to be a plug-in is one EngineError naming the path and what failed.
#include "comparisons/io/source_dir.h"
#include "comparisons/engines/outside/engine_error.h"
#include "comparisons/engines/outside/plugin_engine.h"
#include "comparisons/engines/outside/plugin_library.h"
#include "tests/support/outside_fixtures.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace tecido::outside {
namespace {

std::string load_error(const std::string& path) {
  try {
    PluginLibrary::load(path);
  } catch (const EngineError& e) {
    return e.what();
  }
  return "";
}

TEST(PluginLibrary, LoadsTheExampleTable) {
  const auto lib = PluginLibrary::load(testing::kExamplePlugin);
  ASSERT_EQ(lib->table().abi_version, static_cast<std::uint32_t>(TECIDO_PLUGIN_ABI_VERSION));
  ASSERT_EQ(lib->table().engine_count, 3u);
  EXPECT_STREQ(lib->table().engines[0].name, "mt-plugin");
  EXPECT_STREQ(lib->table().engines[1].name, "euler-plugin");
  EXPECT_EQ(lib->table().engines[1].claimed_order, 1.0);
  EXPECT_STREQ(lib->table().engines[2].name, "sampled-ccd");
  EXPECT_NE(lib->table().engines[2].ccd_vertex_face, nullptr);
  EXPECT_NE(lib->table().engines[2].ccd_edge_edge, nullptr);
  EXPECT_EQ(lib->table().engines[2].tri_tri, nullptr);
  EXPECT_EQ(lib->door(), "plug-in " + testing::kExamplePlugin + " (ABI 1)");
}

// A report names a plug-in by its absolute path, however it was given (README: "the report names
// it by its absolute path").
TEST(PluginLibrary, ARelativePathIsNamedAbsolutely) {
  const std::filesystem::path abs(testing::kExamplePlugin);
  std::string rel = std::filesystem::relative(abs).string();  // against the working directory
  if (rel.find('/') == std::string::npos) rel = "./" + rel;   // a bare name would be searched for
  ASSERT_NE(rel, abs.string());
  const auto lib = PluginLibrary::load(rel);
  EXPECT_EQ(lib->path(), abs.lexically_normal().string());
  EXPECT_EQ(lib->door(), "plug-in " + abs.lexically_normal().string() + " (ABI 1)");
}

TEST(PluginLibrary, MissingFileNamesThePathAndDlopen) {
  const std::string e = load_error("/nonexistent/libnothing.so");
  EXPECT_NE(e.find("plug-in /nonexistent/libnothing.so: dlopen:"), std::string::npos) << e;
  EXPECT_NE(e.find("No such file"), std::string::npos) << e;
}

TEST(PluginLibrary, NotASharedLibrary) {
  const std::string e = load_error(TECIDO_SOURCE_DIR "/README.md");
  EXPECT_NE(e.find("README.md: dlopen:"), std::string::npos) << e;
}

TEST(PluginLibrary, MissingSymbolIsNamed) {
  const std::string e = load_error(testing::kNoEntryPlugin);
  EXPECT_NE(e.find(testing::kNoEntryPlugin + ": tecido_plugin_entry: symbol not found"), std::string::npos) << e;
}

TEST(PluginLibrary, AbiMismatchNamesBothVersions) {
  const std::string e = load_error(testing::kFutureAbiPlugin);
  EXPECT_NE(e.find("ABI version mismatch"), std::string::npos) << e;
  EXPECT_NE(e.find("built for ABI 99"), std::string::npos) << e;
  EXPECT_NE(e.find("speaks ABI 1"), std::string::npos) << e;
}

TEST(PluginLibrary, EngineNames) {
  EXPECT_TRUE(valid_engine_name("euler-plugin"));
  EXPECT_TRUE(valid_engine_name("a.b_C9"));
  EXPECT_FALSE(valid_engine_name(""));
  EXPECT_FALSE(valid_engine_name("-x"));
  EXPECT_FALSE(valid_engine_name("a,b"));  // would break --engines lists
  EXPECT_FALSE(valid_engine_name("a b"));
  EXPECT_FALSE(valid_engine_name(std::string(65, 'a')));
}

}  // namespace
}  // namespace tecido::outside

namespace tecido::outside {
namespace {

int answers_no(const double*, const double*) { return 0; }

// The harness library (include/tecido/harness.h) registers a caller's tables in-process: checked
// as a loaded table is, named "in-process LABEL", with no option of the command line to replay it.
TEST(PluginLibrary, AnInProcessTableIsCheckedAndNamedAsSuch) {
  tecido_engine e{};
  e.name = "mine";
  e.tri_tri = &answers_no;
  tecido_plugin table{TECIDO_PLUGIN_ABI_VERSION, 1, &e};
  const auto lib = PluginLibrary::in_process(&table, "test table");
  EXPECT_FALSE(lib->loaded());
  EXPECT_EQ(lib->door(), "in-process test table (ABI 1)");
  EXPECT_EQ(plugin_engines(lib).front()->door_option(), "");

  e.name = "not a name";
  try {
    PluginLibrary::in_process(&table, "test table");
    ADD_FAILURE() << "a bad engine name was accepted";
  } catch (const EngineError& err) {
    EXPECT_NE(std::string(err.what()).find("in-process test table"), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find("not 1-64 of"), std::string::npos) << err.what();
  }
  e.name = "mine";
  table.abi_version = TECIDO_PLUGIN_ABI_VERSION + 1;
  EXPECT_THROW(PluginLibrary::in_process(&table, "test table"), EngineError);
}

}  // namespace
}  // namespace tecido::outside
