// comparisons/stats/ against worked values from published sources or hand computation, each cited
// beside its check: Student t critical values (NIST/SEMATECH e-Handbook of Statistical Methods,
// table 1.3.6.7.2), the exact binomial test (R's binom.test example after Conover 1971, and sums of
// integers by hand), Wilson's interval (Newcombe 1998, Statistics in Medicine 17:857-872, table I),
// Holm's adjustment and Spearman's rho (the Wikipedia article's worked example) by hand.
#include "comparisons/stats/stats.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::stats {
namespace {

// One-sided 95% critical values t_{0.95, df} (NIST table 1.3.6.7.2): P(T > t) = 0.05.
constexpr double kT95_4 = 2.132, kT95_9 = 1.833;

TEST(Stats, OneSidedTPValuesAtTabulatedCriticalValues) {
  // A sample mean 1.0 with se 0.1 and df 9: t = (1.0 - value) / 0.1.
  const Estimate e{1.0, 0.1, 9.0};
  EXPECT_NEAR(p_above(e, 1.0 - kT95_9 * 0.1), 0.05, 2e-4);  // t = 1.833
  EXPECT_NEAR(p_below(e, 1.0 + kT95_9 * 0.1), 0.05, 2e-4);
  EXPECT_NEAR(p_two_sided(e, 1.0 + 2.262 * 0.1), 0.05, 2e-4);  // two-sided 95%: 2.262 (df 9)
  EXPECT_DOUBLE_EQ(p_above(e, 1.0), 0.5);
  const Interval i90 = t_interval(e, 0.90);
  EXPECT_NEAR(i90.lo, 1.0 - kT95_9 * 0.1, 1e-4);
  EXPECT_NEAR(i90.hi, 1.0 + kT95_9 * 0.1, 1e-4);
}

TEST(Stats, MeanAndWelchEstimatesByHand) {
  // {1, 2, 3, 4, 5}: mean 3, sd sqrt(2.5), se sqrt(0.5), df 4.
  const Estimate m = mean_estimate(summarize({1, 2, 3, 4, 5}));
  EXPECT_DOUBLE_EQ(m.value, 3.0);
  EXPECT_NEAR(m.se, std::sqrt(0.5), 1e-15);
  EXPECT_DOUBLE_EQ(m.df, 4.0);
  EXPECT_NEAR(p_above(m, 3.0 - kT95_4 * std::sqrt(0.5)), 0.05, 2e-4);
  // Welch: a = {1..5} (se^2 0.5, n 5), b = {2, 4, 6} (mean 4, sd 2, se^2 4/3, n 3):
  // se = sqrt(0.5 + 4/3); df = (0.5 + 4/3)^2 / (0.25/4 + (16/9)/2) = 3.3611 / 0.95139 = 3.5328.
  const Estimate w = welch_estimate(summarize({1, 2, 3, 4, 5}), summarize({2, 4, 6}));
  EXPECT_DOUBLE_EQ(w.value, -1.0);
  EXPECT_NEAR(w.se, std::sqrt(0.5 + 4.0 / 3.0), 1e-14);
  EXPECT_NEAR(w.df, (11.0 / 6.0) * (11.0 / 6.0) / (0.0625 + 8.0 / 9.0), 1e-12);
}

TEST(Stats, DataWithoutVariationCannotBeTested) {
  const Summary flat = summarize({0.2, 0.2, 0.2});
  EXPECT_TRUE(flat.without_variation());
  EXPECT_FALSE(summarize({0.2}).without_variation());
  EXPECT_FALSE(summarize({0.2, 0.3}).without_variation());
  const Estimate e = mean_estimate(flat);
  EXPECT_FALSE(e.usable());
  EXPECT_TRUE(std::isnan(p_above(e, 0.0)));
  EXPECT_TRUE(std::isnan(tost(e, -0.1, 0.1).p));
  EXPECT_FALSE(tost(e, -0.1, 0.1).ci90.defined());
  EXPECT_TRUE(std::isnan(p_above(mean_estimate(summarize({0.2})), 0.0)));
}

TEST(Stats, TostIsTheNinetyPercentIntervalInsideTheBand) {
  // Estimate 0 +- se 0.1, df 9: p_lower = P(T >= (0 - lo) / 0.1). With lo = -1.833 * 0.1 each
  // one-sided p is 0.05 (the table's value), so the 90% interval just touches the band.
  const Estimate e{0.0, 0.1, 9.0};
  const Tost at = tost(e, -kT95_9 * 0.1, kT95_9 * 0.1);
  EXPECT_NEAR(at.p_lower, 0.05, 2e-4);
  EXPECT_NEAR(at.p_upper, 0.05, 2e-4);
  EXPECT_NEAR(at.p, 0.05, 2e-4);
  EXPECT_NEAR(at.ci90.lo, -kT95_9 * 0.1, 1e-4);
  const Tost wide = tost(e, -0.5, 0.5);  // t = 5: equivalent
  EXPECT_LT(wide.p, 0.001);
  EXPECT_GT(wide.p_outside, 0.99);
  const Tost narrow = tost(e, -0.05, 0.05);  // the interval spills over: not equivalent
  EXPECT_GT(narrow.p, 0.3);
  // Wholly outside: estimate 1.0, band [-0.1, 0.1]: t = (1.0 - 0.1) / 0.1 = 9 above the band.
  const Tost out = tost({1.0, 0.1, 9.0}, -0.1, 0.1);
  EXPECT_GT(out.p, 0.99);
  EXPECT_LT(out.p_outside, 1e-4);
  // A shifted band, as for "ours equals the seed's -16%": equivalence is about the distance.
  EXPECT_NEAR(tost({-0.16, 0.1, 9.0}, -0.16 - kT95_9 * 0.1, -0.16 + kT95_9 * 0.1).p, 0.05, 2e-4);
}

TEST(Stats, ExactBinomialTwoSidedTest) {
  // R's binom.test example (Conover 1971, p. 97): 682 giant of 925 plants against p = 3/4 gives
  // p-value 0.3825.
  EXPECT_NEAR(binomial_two_sided_p(682, 925, 0.75), 0.3825, 5e-5);
  // By hand: n = 10, p = 1/2, k = 2: the outcomes no likelier than 2 are 0, 1, 2, 8, 9, 10:
  // 2 (1 + 10 + 45) / 1024 = 0.109375.
  EXPECT_NEAR(binomial_two_sided_p(2, 10, 0.5), 0.109375, 1e-12);
  EXPECT_NEAR(binomial_two_sided_p(5, 10, 0.5), 1.0, 1e-12);
  // 0 of 66 outside 95% intervals: P(0) = 0.95^66 = 0.0340; outcomes no likelier: 0 and >= 7;
  // the exact sum in rationals is 0.0802818 (two-sided: the test does not reject at 5%).
  EXPECT_NEAR(binomial_pmf(0, 66, 0.05), std::pow(0.95, 66), 1e-15);
  EXPECT_NEAR(binomial_two_sided_p(0, 66, 0.05), 0.0802818, 1e-6);
  EXPECT_NEAR(binomial_two_sided_p(9, 66, 0.05), 0.00545799, 1e-7);  // too many outside: rejects
  EXPECT_TRUE(std::isnan(binomial_two_sided_p(3, 0, 0.05)));
}

TEST(Stats, ExactBinomialEquivalence) {
  // The count outside in [0.01, 0.14] for n = 66 (exact sums in rationals):
  // k = 3: P(X >= 3 | 0.01) = 0.0286977, P(X <= 3 | 0.14) = 0.0126410 -> p = 0.0286977;
  // k = 2: P(X >= 2 | 0.01) = 0.1414381 -> not equivalent; k = 5: P(X <= 5 | 0.14) = 0.0852497.
  EXPECT_NEAR(binomial_tost_p(3, 66, 0.01, 0.14), 0.0286977, 1e-6);
  EXPECT_NEAR(binomial_tost_p(4, 66, 0.01, 0.14), 0.0366947, 1e-6);
  EXPECT_NEAR(binomial_tost_p(2, 66, 0.01, 0.14), 0.1414381, 1e-6);
  EXPECT_NEAR(binomial_tost_p(5, 66, 0.01, 0.14), 0.0852497, 1e-6);
  EXPECT_NEAR(binomial_upper_tail(16, 18, 0.5), 172.0 / 262144.0, 1e-15);  // (C(18,16)+C(18,17)+1) / 2^18
  EXPECT_NEAR(binomial_lower_tail(2, 18, 0.5), 172.0 / 262144.0, 1e-15);
}

TEST(Stats, WilsonIntervalMatchesNewcombe1998) {
  // Newcombe (1998), table I, method 3 (score interval without continuity correction).
  const struct {
    int k, n;
    double lo, hi;
  } table[] = {{81, 263, 0.2553, 0.3662}, {15, 148, 0.0624, 0.1605}, {0, 20, 0.0, 0.1611}, {1, 29, 0.0061, 0.1718}};
  for (const auto& r : table) {
    const Interval i = wilson_interval(r.k, r.n);
    EXPECT_NEAR(i.lo, r.lo, 5e-5) << r.k << "/" << r.n;
    EXPECT_NEAR(i.hi, r.hi, 5e-5) << r.k << "/" << r.n;
  }
  EXPECT_FALSE(wilson_interval(1, 0).defined());
}

TEST(Stats, HolmAdjustmentByHand) {
  // p = {0.01, 0.04, 0.03, 0.005}, m = 4. Ascending 0.005, 0.01, 0.03, 0.04 times 4, 3, 2, 1:
  // 0.02, 0.03, 0.06, 0.04 -> running maximum 0.02, 0.03, 0.06, 0.06.
  const auto a = holm_adjust({0.01, 0.04, 0.03, 0.005});
  ASSERT_EQ(a.size(), 4u);
  EXPECT_NEAR(a[0], 0.03, 1e-15);
  EXPECT_NEAR(a[1], 0.06, 1e-15);
  EXPECT_NEAR(a[2], 0.06, 1e-15);
  EXPECT_NEAR(a[3], 0.02, 1e-15);
  // A test that could not be run is not in the family: m = 2 here, and adjusted p caps at 1.
  const auto b = holm_adjust({0.6, std::nan(""), 0.01});
  EXPECT_NEAR(b[0], 0.6, 1e-15);
  EXPECT_TRUE(std::isnan(b[1]));
  EXPECT_NEAR(b[2], 0.02, 1e-15);
  EXPECT_DOUBLE_EQ(holm_adjust({0.7, 0.8})[0], 1.0);
}

TEST(Stats, SpearmanWorkedExampleAndFisherInterval) {
  // Wikipedia, "Spearman's rank correlation coefficient", the IQ / hours of TV example:
  // sum d^2 = 194, rho = 1 - 6 * 194 / (10 * 99) = -29/165 = -0.175758.
  const std::vector<double> iq{106, 100, 86, 101, 99, 103, 97, 113, 112, 110};
  const std::vector<double> tv{7, 27, 2, 50, 28, 29, 20, 12, 6, 17};
  const Correlation c = spearman(iq, tv);
  EXPECT_NEAR(c.r, -29.0 / 165.0, 1e-14);
  EXPECT_EQ(c.n, 10u);
  // Fisher z by hand: atanh(-29/165) = -0.177602; half width 1.959964 sqrt(1.06 / 7) = 0.762697;
  // tanh(-0.940299) = -0.735359, tanh(0.585095) = 0.526359.
  EXPECT_NEAR(c.ci95.lo, std::tanh(std::atanh(-29.0 / 165.0) - 1.959963984540054 * std::sqrt(1.06 / 7.0)), 1e-12);
  EXPECT_NEAR(c.ci95.lo, -0.735359, 2e-6);
  EXPECT_NEAR(c.ci95.hi, 0.526359, 2e-6);
  // Ties take mid-ranks: {1, 2, 2, 3} -> 1, 2.5, 2.5, 4.
  const auto r = mid_ranks({1, 2, 2, 3});
  EXPECT_EQ(r, (std::vector<double>{1, 2.5, 2.5, 4}));
  // A monotone but non-linear relation: Spearman 1, Pearson below 1.
  EXPECT_NEAR(spearman({1, 2, 3, 4, 5}, {1, 4, 9, 16, 250}).r, 1.0, 1e-15);
  EXPECT_LT(pearson({1, 2, 3, 4, 5}, {1, 4, 9, 16, 250}), 0.8);
  EXPECT_FALSE(spearman({1, 2, 3}, {3, 1, 2}).ci95.defined());  // n < 4: no interval
}

TEST(Stats, NormalQuantile) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959963984540054, 1e-12);
  EXPECT_NEAR(normal_quantile(0.95), 1.6448536269514722, 1e-12);
  EXPECT_NEAR(normal_cdf(0.0), 0.5, 1e-16);
  EXPECT_TRUE(std::isnan(normal_quantile(0.0)));
}

}  // namespace
}  // namespace tecido::stats
