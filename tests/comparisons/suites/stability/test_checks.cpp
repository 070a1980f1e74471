// The stability suite's declared checks (comparisons/suites/stability/checks.*): the same names
// whatever the tolerance file says and whether --quick or not; every band read from the file.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/stability/cases.h"
#include "comparisons/suites/stability/checks.h"
#include "comparisons/io/input_error.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace tecido::suites::stability {
namespace {

io::Json tolerance_doc() {
  std::ifstream in(std::string(TECIDO_SOURCE_DIR) + "/data/tolerances.json");
  return io::Json::parse(in);
}

/// The document with every number of /stability multiplied by `f`.
io::Json scaled(io::Json doc, double f) {
  for (auto it = doc["stability"].begin(); it != doc["stability"].end(); ++it)
    if (it.value().is_number()) it.value() = it.value().get<double>() * f;
  return doc;
}

std::vector<std::string> names(const CheckList& list) {
  std::vector<std::string> out;
  for (const Check& c : list.finish()) out.push_back(c.name);
  return out;
}

TEST(StabilityChecks, TheNamesAreFixedBeforeAnythingRuns) {
  const std::vector<std::string> want = {
      "stability/symplectic/h_omega_ratio_min", "stability/symplectic/h_omega_ratio_max",
      "stability/symplectic/grid_spread",       "stability/rk4/h_omega_ratio_min",
      "stability/rk4/h_omega_ratio_max",        "stability/rk4/grid_spread",
      "stability/euler/growth_rel_error",       "stability/midpoint/growth_rel_error",
      "stability/euler/horizon_ratio_min",      "stability/euler/horizon_ratio_max",
      "stability/midpoint/horizon_ratio_min",   "stability/midpoint/horizon_ratio_max",
      "stability/extremes/offset_error_ulps_per_step",
      "stability/extremes/mass_ratio_min",      "stability/extremes/mass_ratio_max",
      "stability/extremes/near_zero_nonfinite", "stability/extremes/zero_length_force",
      "stability/extremes/rest_max_sink",       "stability/extremes/rest_max_jitter",
      "stability/extremes/tunnel_wrong_side_steps"};
  const Tolerances normal(tolerance_doc(), "tol.json"), other(scaled(tolerance_doc(), 1.37), "other.json");
  for (bool quick : {true, false}) {
    for (const Tolerances* tol : {&normal, &other}) {
      const CheckList list = declare_checks(settings(quick), extreme_groups(), *tol);
      EXPECT_EQ(names(list), want) << quick << " " << tol->file();
      // Nothing has run: every check is failed "not produced".
      for (const Check& c : list.finish()) EXPECT_EQ(c.reason, "not produced") << c.name;
    }
  }
}

TEST(StabilityChecks, EveryBandComesFromTheFile) {
  const io::Json doc = tolerance_doc();
  const Tolerances normal(doc, "tol.json"), other(scaled(doc, 1.37), "other.json");
  const std::vector<Check> a = declare_checks(settings(true), extreme_groups(), normal).finish();
  const std::vector<Check> b = declare_checks(settings(true), extreme_groups(), other).finish();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_FALSE(a[i].tolerance.empty()) << a[i].name;
    // Every end of every band scales with the file (an end at 0 stays 0; inf is no end).
    EXPECT_DOUBLE_EQ(b[i].lo, a[i].lo * 1.37) << a[i].name;
    EXPECT_DOUBLE_EQ(b[i].hi, a[i].hi * 1.37) << a[i].name;
    // And the pointer names an entry of /stability.
    const std::string first = a[i].tolerance.substr(0, a[i].tolerance.find(' '));
    EXPECT_EQ(first.rfind("/stability/", 0), 0u) << a[i].tolerance;
    EXPECT_TRUE(doc.contains(io::Json::json_pointer(first))) << first;
  }
  EXPECT_EQ(a[0].lo, doc["stability"]["ratio_lo"].get<double>());
  EXPECT_EQ(a[0].hi, doc["stability"]["ratio_hi"].get<double>());
}

TEST(StabilityChecks, TheFileHoldsBandsOnly) {
  // The run's parameters left the file: its /stability numbers are each some check's or verdict's band.
  const io::Json doc = tolerance_doc();
  for (const char* gone : {"periods", "amplitude_bound"}) EXPECT_FALSE(doc["stability"].contains(gone)) << gone;
  const Tolerances tol(doc, "tol.json");
  std::string used;
  for (const Check& c : declare_checks(settings(false), extreme_groups(), tol).finish()) used += " " + c.tolerance + " ";
  for (const auto& [name, band] : verdict_bands(tol)) used += " " + band.source + " ";
  for (auto it = doc["stability"].begin(); it != doc["stability"].end(); ++it) {
    if (it.key()[0] == '_') continue;
    EXPECT_NE(used.find(" /stability/" + it.key() + " "), std::string::npos) << it.key() << " is no band";
  }
}

TEST(StabilityChecks, AMissingBandIsBadInput) {
  io::Json doc = tolerance_doc();
  doc["stability"].erase("tunnel_wrong_side_steps");
  const Tolerances tol(doc, "tol.json");
  try {
    declare_checks(settings(true), extreme_groups(), tol);
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/stability/tunnel_wrong_side_steps"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tecido::suites::stability
