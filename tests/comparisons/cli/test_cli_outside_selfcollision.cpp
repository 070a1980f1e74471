// Outside engines answering tri_tri in the selfcollision suite: run on core's broad-phase
// candidates of each recorded frame and scored against the exact truth. The example plug-in's
// Moller-Trumbore with the seed's AND rule only ever reports pairs where edges of both triangles
// cross the other (true intersections), and misses the pairs where only one triangle's edges do:
// its precision is 1 and its recall below, and its recall checks fail. The Python example's rule
// (an edge of either crosses the other) finds every crossing pair of these frames.
#include "tests/support/cli_runner.h"
#include "tests/support/outside_fixtures.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <filesystem>

namespace tecido {
namespace {

using nlohmann::json;
using testing::quoted;
using testing::run_cli;

TEST(CliOutsideSelfCollision, OutsideTriangleTestsAreScoredAgainstTheTruth) {
  const auto dir = testing::temp_dir("outside-selfcollision");
  const auto r = run_cli("suite selfcollision --quick --threads 2 --plugin " + quoted(testing::kExamplePlugin) +
                         " --engine-cmd " + quoted("py=" + testing::kPythonEngine) + " --engines mt-plugin,py --out " +
                         quoted(dir.string()));
  EXPECT_EQ(r.code, 1) << r.err;  // mt-plugin's recall
  const json report = json::parse(testing::slurp(dir / "report.json"));
  int mt_checks = 0, py_checks = 0;
  for (const auto& c : report["suites"][0]["checks"]) {
    const std::string name = c["name"];
    EXPECT_EQ(name.find("/core/"), std::string::npos) << name;  // --engines: core and fcl did not run
    EXPECT_EQ(name.find("/fcl/"), std::string::npos) << name;
    const bool mt = name.rfind("selfcollision/mt-plugin/", 0) == 0, py = name.rfind("selfcollision/py/", 0) == 0;
    if (!mt && !py) continue;
    EXPECT_EQ(c["tolerance"], "/selfcollision/outside_min") << name;
    mt_checks += mt, py_checks += py;
    const bool recall = name.size() > 6 && name.compare(name.size() - 6, 6, "recall") == 0;
    if (py || !recall) {
      EXPECT_TRUE(c["pass"].get<bool>()) << c.dump();
    } else {
      EXPECT_FALSE(c["pass"].get<bool>()) << c.dump();
      EXPECT_LT(c["value"].get<double>(), 1.0);
    }
  }
  EXPECT_EQ(mt_checks, 4);  // precision and recall on both sources
  EXPECT_EQ(py_checks, 4);
  EXPECT_NE(testing::slurp(dir / "report.md").find("process `" + testing::kPythonEngine + "`"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
