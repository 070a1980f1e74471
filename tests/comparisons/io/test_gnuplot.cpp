// Plots (comparisons/io/gnuplot.h): the picture appears whole or not at all, and no temporary
// file stays behind.
#include "tests/support/rejection.h"
#include "comparisons/io/gnuplot.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

const char* kHead = "set terminal svg size 200,100\nset output 'p.svg'\n";

TEST(Gnuplot, APictureIsRenamedIntoPlaceOnlyWhenComplete) {
  if (!io::gnuplot_available()) GTEST_SKIP() << "gnuplot is not on PATH";
  const auto dir = testing::temp_dir("gnuplot");
  ASSERT_TRUE(io::run_gnuplot(dir.string(), "p", std::string(kHead) + "plot x\n"));
  EXPECT_NE(testing::slurp(dir / "p.svg").find("</svg>"), std::string::npos);
  EXPECT_EQ(testing::slurp(dir / "p.gp"), std::string(kHead) + "plot x\n");  // the script as given
  std::filesystem::remove(dir / "p.svg");
  // A script that fails after opening its output: no picture, no temporary file.
  EXPECT_FALSE(io::run_gnuplot(dir.string(), "p", std::string(kHead) + "plot x\nthis is not gnuplot\n"));
  EXPECT_FALSE(std::filesystem::exists(dir / "p.svg"));
  EXPECT_TRUE(testing::files_named(dir, ".tmp.").empty());
  std::filesystem::remove_all(dir);
}

// The directory reaches gnuplot as an argument of chdir, never through a shell.
TEST(Gnuplot, PathsAreNotInterpretedByAShell) {
  if (!io::gnuplot_available()) GTEST_SKIP() << "gnuplot is not on PATH";
  const auto base = testing::temp_dir("gnuplot-quote");
  const auto dir = base / "it's $(touch pwned) here";
  ASSERT_TRUE(io::run_gnuplot(dir.string(), "p", std::string(kHead) + "plot x\n"));
  EXPECT_TRUE(std::filesystem::exists(dir / "p.svg"));
  EXPECT_FALSE(std::filesystem::exists("pwned"));
  EXPECT_FALSE(std::filesystem::exists(dir / "pwned"));
  std::filesystem::remove_all(base);
}

}  // namespace
}  // namespace tecido
