// comparisons/io/progress.h: the progress bar's line and when it draws.
#include "comparisons/io/progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <thread>
#include <vector>

namespace tecido {
namespace {

TEST(Progress, DrawsOnlyWhenEnabledAndEndsTheLine) {
  EXPECT_EQ(io::Progress::line("sweep", 3, 12, 2.0), "sweep [#######.......................] 3/12  1.50/s  ETA 0:06");
  EXPECT_EQ(io::Progress::line("x", 0, 4, 0.0), "x [..............................] 0/4  0.00/s  ETA --:--");
  EXPECT_EQ(io::Progress::line("x", 4, 4, 1.0).find("ETA 0:00") != std::string::npos, true);
  std::ostringstream on, off;
  {
    io::Progress p(4, "on", on, true), silent(4, "off", off, false);
    std::vector<std::thread> ts;
    for (int t = 0; t < 4; ++t) ts.emplace_back([&] { p.tick(); silent.tick(); });
    for (auto& t : ts) t.join();
  }
  EXPECT_TRUE(off.str().empty());
  const std::string s = on.str();
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.front(), '\r');
  EXPECT_EQ(s.back(), '\n');
  EXPECT_NE(s.find("4/4"), std::string::npos) << s;
  EXPECT_EQ(std::count(s.begin(), s.end(), '\n'), 1);
}

}  // namespace
}  // namespace tecido
