// The notes under the stability suite's extremes table (comparisons/suites/stability/extremes_notes.*):
// every figure comes from the settings, the theory or the group's data, and the stated outcome flips
// when planted data contradicts it.
#include "comparisons/suites/stability/extremes_notes.h"

#include <gtest/gtest.h>

namespace tecido::suites::stability {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const VerdictBands kBands = {{"offset_degraded", Band{0.0, 0.002, "/stability/offset_degraded_fraction"}}};

TEST(ExtremesNotes, OffsetsUseTheLargestOffsetAndItsUlp) {
  io::Json data;
  data["offset"] = io::Json::array();
  data["offset"].push_back({{"kind", "spring"}, {"offset", 1e6}, {"rest_length", 1.0}, {"amplitude", 0.1},
                            {"relative", 1e-7}, {"ulps_per_step", 0.003}});
  data["offset"].push_back({{"kind", "spring"}, {"offset", 1e8}, {"rest_length", 0.01}, {"amplitude", 0.001},
                            {"relative", 0.0011}, {"ulps_per_step", 0.002}});
  data["offset"].push_back({{"kind", "drop"}, {"offset", 1e8}, {"ulps_per_step", 0.25}});
  const std::string md = offset_note(settings(true), data, kBands);
  // ulp(1e8) = 2^-26 = 1.49e-8.
  EXPECT_TRUE(has(md, "at 1e+08 m a double holds positions to ulp = 1.5e-08 m")) << md;
  EXPECT_TRUE(has(md, "the worst run here: 0.25 ulp per step")) << md;
  EXPECT_TRUE(has(md, "the error reached 0.0011 of the amplitude for the 0.01 m spring moving 0.001 m.")) << md;
  EXPECT_TRUE(has(md, "exceeds 0.002 of its amplitude")) << md;
}

TEST(ExtremesNotes, MassRatiosTheoryAgainstMeasurement) {
  io::Json data;
  data["mass_ratio"]["equal"]["symplectic"] = {{"found", true}, {"reference", true}, {"smaller_than_equal", 1.0}};
  data["mass_ratio"]["light"]["symplectic"] = {{"found", true}, {"reference", false}, {"smaller_than_equal", 700.0}};
  data["mass_ratio"]["light"]["rk4"] = {{"found", true}, {"reference", false}, {"smaller_than_equal", 710.0}};
  data["mass_ratio"]["chain"]["rk4"] = {{"found", false}, {"reference", false}};
  const std::string md = mass_ratio_note(settings(true), data);
  // sqrt((1 + 1e6) / 2) = 707.1 for 1 kg : 1e-6 kg.
  EXPECT_TRUE(has(md, "2 of the 3 systems (mass ratios 1 and 1e+06) had a stable step")) << md;
  EXPECT_TRUE(has(md, "707.1x smaller than the equal-mass pair's by theory, 700 to 710x measured")) << md;
}

TEST(ExtremesNotes, NearZeroSaysWhatWasNotFinite) {
  io::Json data;
  data["near_zero"] = {{"nonfinite", 0}, {"runs", 12}, {"deviation_over_l", {79.0, 79.0}}};
  const std::string ok = near_zero_note(settings(true), data);
  EXPECT_TRUE(has(ok, "No NaN or infinity in any of the 12 runs and forces")) << ok;
  EXPECT_TRUE(has(ok, "by 79 times l")) << ok;
  EXPECT_TRUE(has(ok, "up to 1e-09 m here")) << ok;
  EXPECT_TRUE(has(ok, "below about 1.57e-162 m")) << ok;
  data["near_zero"]["nonfinite"] = 2;
  data["near_zero"]["deviation_over_l"] = {70.0, 90.0};
  const std::string bad = near_zero_note(settings(true), data);
  EXPECT_TRUE(has(bad, "2 of the 12 runs and forces were not finite")) << bad;
  EXPECT_TRUE(has(bad, "by 70 to 90 times l")) << bad;
}

TEST(ExtremesNotes, RestingStillOnlyWhenTheDataSaysSo) {
  io::Json data;
  data["resting"] = {{"max_speed", 0.0}, {"max_drift", 0.0}};
  EXPECT_TRUE(has(resting_note(settings(true), data), "stayed still, bit for bit"));
  data["resting"]["max_speed"] = 1e-3;
  const std::string moved = resting_note(settings(true), data);
  EXPECT_FALSE(has(moved, "bit for bit")) << moved;
  EXPECT_TRUE(has(moved, "largest speed was 0.001 m/s")) << moved;
}

TEST(ExtremesNotes, TunnellingCountsWhatTheRunsCounted) {
  io::Json data;
  data["tunnelling"] = {{"wrong_side_steps", 0}, {"runs", 40}, {"max_dt", 10.0}};
  const std::string ok = tunnelling_note(settings(true), data);
  EXPECT_TRUE(has(ok, "in all 40 runs, with steps up to 10 s (at 1000 m/s one step spans 10000 m)")) << ok;
  data["tunnelling"]["wrong_side_steps"] = 3;
  const std::string bad = tunnelling_note(settings(true), data);
  EXPECT_TRUE(has(bad, "yet 3 steps ended below the plane in 40 runs")) << bad;
  EXPECT_FALSE(has(bad, "does not matter")) << bad;
}

TEST(ExtremesNotes, AGroupWithoutDataSaysSo) {
  const std::string md = extremes_notes(settings(true), io::Json::object(), kBands);
  for (const char* title : {"Offsets", "Mass ratios", "Near-zero rest lengths", "Resting contact", "Tunnelling"})
    EXPECT_TRUE(has(md, std::string("**") + title + ".** No result")) << title;
}

}  // namespace
}  // namespace tecido::suites::stability
