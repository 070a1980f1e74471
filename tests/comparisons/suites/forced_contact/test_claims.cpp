// The forced-contact statistics and claim rules on worked cases (comparisons/suites/forced_contact/
// recovery.h, claims.h): recovery from a run's frames, the censored median, Wilson's interval,
// and each claim's verdict on made-up ensembles whose answer is known by hand.
#include "comparisons/suites/forced_contact/claims.h"
#include "comparisons/suites/forced_contact/recovery.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tecido {
namespace {

namespace fc = suites::forced_contact;
using Verdict = suites::self_contact::Verdict;
constexpr double kInf = std::numeric_limits<double>::infinity();

fc::Settings small_settings() {
  fc::Settings s;
  s.holds = {0.03, 3.0};
  s.responses = {SelfCollisionResponse::Gia, SelfCollisionResponse::Impulse};
  s.seeds = 10;
  s.after_release = 4.0;
  s.dwell = 0.5;  // censored at 3.5 s
  return s;
}

TEST(ForcedContactRecovery, FromTheFramesAfterRelease) {
  const fc::Settings s = small_settings();
  fc::RunResult r;
  // dt 0.5: frames at 0.5, 1.0, ... 4.0 s after release. Free from the 4th frame (2.0 s) on.
  fc::decide_recovery({3, 0, 2, 0, 0, 0, 0, 0}, 0.5, s, r);
  EXPECT_TRUE(r.recovered);
  EXPECT_DOUBLE_EQ(r.recovery, 2.0);
  EXPECT_TRUE(r.free_at_end);
  // Free only from 4.0 s: the stretch starts after the censoring time 3.5 s.
  fc::decide_recovery({3, 1, 1, 1, 1, 1, 1, 0}, 0.5, s, r);
  EXPECT_FALSE(r.recovered);
  EXPECT_TRUE(r.free_at_end);
  // Free from 3.5 s exactly: recovered (the stretch lasts the dwell).
  fc::decide_recovery({3, 1, 1, 1, 1, 1, 0, 0}, 0.5, s, r);
  EXPECT_TRUE(r.recovered);
  EXPECT_DOUBLE_EQ(r.recovery, 3.5);
  fc::decide_recovery({0, 0, 0, 1}, 0.5, s, r);
  EXPECT_FALSE(r.recovered);
  EXPECT_FALSE(r.free_at_end);
  EXPECT_DOUBLE_EQ(fc::restricted_time(r, 3.5), 3.5);
}

TEST(ForcedContactRecovery, CensoredMedianAndBootstrap) {
  EXPECT_DOUBLE_EQ(fc::censored_median({1.0, 2.0, kInf}), 2.0);
  EXPECT_EQ(fc::censored_median({1.0, kInf, kInf}), kInf);  // fewer than half recovered: not reached
  EXPECT_DOUBLE_EQ(fc::censored_median({3.0, 1.0, 2.0, 4.0}), 2.0);  // the smallest with half at or below
  EXPECT_TRUE(std::isnan(fc::censored_median({})));
  const auto ci = fc::bootstrap_median_ci({1.0, 1.0, 1.0, 1.0}, 100, 7);
  EXPECT_EQ(ci.lo, 1.0);
  EXPECT_EQ(ci.hi, 1.0);
  const auto wide = fc::bootstrap_median_ci({1.0, 2.0, 3.0, kInf, kInf}, 500, 7);
  EXPECT_GE(wide.lo, 1.0);
  EXPECT_EQ(wide.hi, kInf);
  EXPECT_EQ(wide.lo, fc::bootstrap_median_ci({1.0, 2.0, 3.0, kInf, kInf}, 500, 7).lo);  // deterministic
}

/// An ensemble table: y(h, r, k) given as a recovery time, or +inf for a run that did not recover.
struct Table {
  std::vector<fc::RunResult> store;
  fc::RunTable runs;
  Table(const fc::Settings& s, const std::function<double(int, int, int)>& t) {
    store.reserve(s.holds.size() * s.responses.size() * s.seeds);
    runs.assign(s.holds.size(), std::vector<std::vector<const fc::RunResult*>>(s.responses.size()));
    for (int h = 0; h < static_cast<int>(s.holds.size()); ++h)
      for (int r = 0; r < static_cast<int>(s.responses.size()); ++r)
        for (int k = 0; k < s.seeds; ++k) {
          fc::RunResult run;
          const double v = t(h, r, k);
          run.recovered = std::isfinite(v);
          run.recovery = run.recovered ? v : 0.0;
          store.push_back(run);
          runs[h][r].push_back(&store.back());
        }
  }
};

TEST(ForcedContactClaims, TheSeedsArgumentHoldingGivesFourReproduced) {
  const fc::Settings s = small_settings();
  // GIA (r = 0) recovers at 0.5 + k/20 s whatever the hold; impulse (r = 1) recovers late after
  // a short hold and never after a long one.
  const Table t(s, [](int h, int r, int k) { return r == 0 ? 0.5 + k / 20.0 + h * (k % 2 ? 0.01 : -0.01) : (h == 0 ? 2.0 + k / 10.0 : kInf); });
  const auto c = fc::forced_claims(t.runs, s);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0].id, "gia-recovers");
  EXPECT_DOUBLE_EQ(c[0].observed, 1.0);
  // Wilson for 20 of 20: lower end n / (n + z^2) = 20 / 23.8415 = 0.8389 > 0.8.
  EXPECT_NEAR(c[0].ci95.lo, 20.0 / (20.0 + 1.959963984540054 * 1.959963984540054), 1e-12);
  EXPECT_EQ(c[0].verdict, Verdict::Reproduced);
  EXPECT_EQ(c[1].id, "impulse-later");
  EXPECT_EQ(c[1].n, 20u);
  EXPECT_EQ(c[1].verdict, Verdict::Reproduced);
  EXPECT_EQ(c[2].id, "impulse-hold");
  // Per seed: 3.5 - (2.0 + k/10): mean 3.5 - 2.45 = 1.05.
  EXPECT_NEAR(c[2].observed, 1.05, 1e-12);
  EXPECT_EQ(c[2].verdict, Verdict::Reproduced);
  EXPECT_EQ(c[3].id, "gia-hold-level");
  EXPECT_NEAR(c[3].observed, 0.0, 1e-12);  // +0.01 for odd k, -0.01 for even k
  EXPECT_EQ(c[3].verdict, Verdict::Reproduced);
}

TEST(ForcedContactClaims, TheSeedsArgumentFailingGivesNotReproduced) {
  const fc::Settings s = small_settings();
  // GIA never recovers; impulse recovers early, sooner after the long hold; GIA's time grows by 1 s.
  const Table t(s, [](int h, int r, int k) { return r == 0 ? (h == 0 ? 1.0 + k / 100.0 : 2.0 + k / 50.0) : 0.2 + k / 100.0 - h * (0.1 + k / 200.0); });
  fc::Settings never = s;
  const Table t2(s, [](int, int r, int k) { return r == 0 ? kInf : 0.2 + k / 100.0; });
  const auto c = fc::forced_claims(t.runs, s);
  EXPECT_EQ(c[1].verdict, Verdict::NotReproduced);  // impulse sooner than GIA
  EXPECT_EQ(c[2].verdict, Verdict::NotReproduced);  // impulse sooner after the long hold
  EXPECT_EQ(c[3].verdict, Verdict::NotReproduced);  // GIA later by about 1 s, outside +-0.35 s
  const auto c2 = fc::forced_claims(t2.runs, never);
  EXPECT_EQ(c2[0].verdict, Verdict::NotReproduced);  // 0 of 20: Wilson upper end 0.16 < 0.8
}

TEST(ForcedContactClaims, DataWithoutVariationIsInconclusive) {
  const fc::Settings s = small_settings();
  // Every run censored: every difference is 0 with sd 0.
  const Table t(s, [](int, int, int) { return kInf; });
  const auto c = fc::forced_claims(t.runs, s);
  for (std::size_t k = 1; k < 4; ++k) {
    EXPECT_EQ(c[k].verdict, Verdict::Inconclusive) << c[k].id;
    EXPECT_NE(c[k].reason.find("do not vary"), std::string::npos) << c[k].reason;
  }
  // An interval straddling the margin: inconclusive.
  const Table wide(s, [](int h, int r, int k) { return r == 0 ? 1.0 + h * (k % 2 ? 0.8 : -0.4) : 1.0; });
  EXPECT_EQ(fc::forced_claims(wide.runs, s)[3].verdict, Verdict::Inconclusive);
}

TEST(ForcedContactClaims, MissingRunsAreLeftOut) {
  fc::Settings s = small_settings();
  s.seeds = 1;  // one pair per hold: impulse-hold and gia-hold-level have 1 value, no interval
  const Table t(s, [](int, int r, int) { return r == 0 ? 1.0 : 2.0; });
  const auto c = fc::forced_claims(t.runs, s);
  EXPECT_EQ(c[2].verdict, Verdict::Inconclusive);
  EXPECT_NE(c[2].reason.find("2 needed"), std::string::npos);
}

}  // namespace
}  // namespace tecido
