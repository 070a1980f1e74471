// Loading plug-ins: the example's table as written in examples/plugin; every way a library can fail
// to be a plug-in is one EngineError naming the path and what failed.
#include "comparisons/engines/outside/engine_error.h"
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
