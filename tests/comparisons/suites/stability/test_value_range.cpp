// ValueRange (comparisons/suites/stability/value_range.*): a min/max that keeps a NaN or a missing
// value and the place it came from, where std::min/std::max would drop it.
#include "comparisons/suites/stability/value_range.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::stability {
namespace {

TEST(ValueRange, MinMaxAndSpread) {
  ValueRange r;
  EXPECT_FALSE(r.complete());
  EXPECT_EQ(r.reason(), "no values");
  r.add(2.0, "a");
  r.add(0.5, "b");
  r.add(1.0, "c");
  ASSERT_TRUE(r.complete());
  EXPECT_EQ(r.lo(), 0.5);
  EXPECT_EQ(r.hi(), 2.0);
  EXPECT_EQ(r.spread(), 3.0);
}

TEST(ValueRange, ANaNIsNotDropped) {
  // What std::max does with a NaN in second place: it keeps the other value.
  EXPECT_EQ(std::max(1.0, std::nan("")), 1.0);
  ValueRange r;
  r.add(1.0, "ks = 1 N/m, m = 1 kg");
  r.add(std::nan(""), "ks = 10 N/m, m = 0.001 kg");
  r.add(3.0, "ks = 100 N/m, m = 1 kg");
  EXPECT_FALSE(r.complete());
  EXPECT_TRUE(std::isnan(r.lo()));
  EXPECT_TRUE(std::isnan(r.hi()));
  EXPECT_TRUE(std::isnan(r.spread()));
  EXPECT_EQ(r.reason(), "NaN at ks = 10 N/m, m = 0.001 kg");
  ValueRange inf;
  inf.add(-INFINITY, "x");
  EXPECT_EQ(inf.reason(), "infinite at x");
}

TEST(ValueRange, TheFirstReasonIsKeptAndIncludeCarriesIt) {
  ValueRange r;
  r.missing("no stable step at A");
  r.missing("no stable step at B");
  EXPECT_EQ(r.reason(), "no stable step at A");
  ValueRange good;
  good.add(4.0, "");
  good.add(5.0, "");
  ValueRange all;
  all.include(good);
  EXPECT_EQ(all.lo(), 4.0);
  EXPECT_EQ(all.hi(), 5.0);
  all.include(r);
  EXPECT_EQ(all.reason(), "no stable step at A");
}

TEST(ValueRange, RecordSetsOrFailsTheCheck) {
  CheckList checks;
  checks.declare("t/ok", Band{0.0, 10.0, "/t/ok"});
  checks.declare("t/missing", Band{0.0, 10.0, "/t/missing"});
  ValueRange ok, missing;
  ok.add(3.0, "");
  missing.add(3.0, "");
  missing.add(std::nan(""), "cell 7");
  record(checks, "t/ok", ok, ok.hi());
  record(checks, "t/missing", missing, missing.hi());
  const std::vector<Check> c = checks.finish();
  EXPECT_TRUE(c[0].pass);
  EXPECT_EQ(c[0].value, 3.0);
  EXPECT_FALSE(c[1].pass);
  EXPECT_EQ(c[1].reason, "NaN at cell 7");
}

}  // namespace
}  // namespace tecido::suites::stability
