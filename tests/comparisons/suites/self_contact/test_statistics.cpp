// comparisons/suites/self_contact/statistics.h against tabulated values (Student t quantiles,
// special cases of the incomplete beta), hand-worked cases (a five-value sample, exact binomial
// tails summed in integers), and the coverage of the intervals on planted normal data.
#include "comparisons/suites/self_contact/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace tecido::suites::self_contact {
namespace {

/// Standard normal deviates by Box-Muller on a fixed generator (the test's own source).
class Normal {
 public:
  explicit Normal(std::uint64_t seed) : g_(seed) {}
  double operator()() {
    const double u1 = 1.0 - static_cast<double>(g_() >> 11) * 0x1.0p-53, u2 = static_cast<double>(g_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
  }

 private:
  std::mt19937_64 g_;
};

TEST(Statistics, StudentTQuantilesMatchTables) {
  // Two-sided 95% critical values (e.g. NIST/SEMATECH e-Handbook, table 1.3.6.7.2).
  const struct {
    double df, t;
  } table[] = {{1, 12.7062047362}, {2, 4.3026527297}, {4, 2.7764451052}, {9, 2.2621571628},
               {19, 2.0930240544}, {29, 2.0452296421}, {100, 1.9839715185}};
  for (const auto& r : table) EXPECT_NEAR(student_t_quantile(0.975, r.df), r.t, 1e-8) << r.df;
  EXPECT_NEAR(student_t_quantile(0.975, 1e7), 1.959963985, 1e-6);  // the normal's
  EXPECT_NEAR(student_t_quantile(0.025, 9), -2.2621571628, 1e-8);
  EXPECT_DOUBLE_EQ(student_t_cdf(0.0, 3.5), 0.5);
  // df = 1 is Cauchy: F(t) = 1/2 + atan(t) / pi; df = 2 has F(t) = 1/2 + t / (2 sqrt(2 + t^2)).
  for (double t : {-3.0, -0.4, 0.7, 5.0}) {
    EXPECT_NEAR(student_t_cdf(t, 1), 0.5 + std::atan(t) / M_PI, 1e-13) << t;
    EXPECT_NEAR(student_t_cdf(t, 2), 0.5 + t / (2.0 * std::sqrt(2.0 + t * t)), 1e-13) << t;
  }
  EXPECT_TRUE(std::isnan(student_t_quantile(1.0, 3)));
  EXPECT_TRUE(std::isnan(student_t_quantile(0.5, 0)));
}

TEST(Statistics, SpecialFunctionsAtKnownPoints) {
  EXPECT_NEAR(log_gamma(1.0), 0.0, 1e-14);
  EXPECT_NEAR(log_gamma(5.0), std::log(24.0), 1e-13);
  EXPECT_NEAR(log_gamma(0.5), 0.5 * std::log(M_PI), 1e-13);
  EXPECT_NEAR(log_gamma(101.0), 363.73937555556347, 1e-10);  // ln(100!)
  for (double x : {0.1, 0.35, 0.8}) {
    EXPECT_NEAR(incomplete_beta(1, 1, x), x, 1e-14);
    EXPECT_NEAR(incomplete_beta(3, 1, x), x * x * x, 1e-14);
    EXPECT_NEAR(incomplete_beta(1, 4, x), 1.0 - std::pow(1.0 - x, 4), 1e-14);
  }
  EXPECT_NEAR(incomplete_beta(7.5, 7.5, 0.5), 0.5, 1e-14);
  EXPECT_EQ(incomplete_beta(2, 3, 0.0), 0.0);
  EXPECT_EQ(incomplete_beta(2, 3, 1.0), 1.0);
}

TEST(Statistics, SummaryOfAHandWorkedSample) {
  const Summary s = summarize({1, 2, 3, 4, 5});
  EXPECT_EQ(s.n, 5u);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_NEAR(s.sd, std::sqrt(2.5), 1e-15);
  EXPECT_NEAR(s.se, std::sqrt(0.5), 1e-15);
  const double t4 = 2.7764451052;
  EXPECT_NEAR(s.ci95.lo, 3.0 - t4 * std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(s.ci95.hi, 3.0 + t4 * std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(s.pi95.hi, 3.0 + t4 * std::sqrt(2.5 * 1.2), 1e-9);
  const Summary one = summarize({0.3});
  EXPECT_DOUBLE_EQ(one.mean, 0.3);
  EXPECT_TRUE(std::isnan(one.sd));
  EXPECT_TRUE(std::isnan(one.ci95.lo));
  EXPECT_TRUE(std::isnan(summarize({}).mean));
}

TEST(Statistics, BinomialTailsMatchExactSums) {
  // P(X >= 16 | n = 18, 1/2) = (C(18,16) + C(18,17) + C(18,18)) / 2^18 = 172 / 262144.
  EXPECT_NEAR(sign_test_p(16, 18), 172.0 / 262144.0, 1e-15);
  EXPECT_NEAR(sign_test_p(15, 18), (816.0 + 172.0) / 262144.0, 1e-15);
  EXPECT_DOUBLE_EQ(sign_test_p(0, 18), 1.0);
  EXPECT_EQ(sign_test_p(19, 18), 0.0);
  // P(X >= 4 | n = 66, 0.05) = 1 - sum_{k<4} C(66,k) 0.05^k 0.95^(66-k), the terms by recurrence.
  double term = std::pow(0.95, 66), below = 0.0;
  for (int k = 0; k < 4; ++k) {
    below += term;
    term *= (66.0 - k) / (k + 1.0) * (0.05 / 0.95);
  }
  EXPECT_NEAR(binomial_upper_tail(4, 66, 0.05), 1.0 - below, 1e-13);
}

TEST(Statistics, WilsonPearsonAndPercentile) {
  const Interval w = wilson_ci95(0, 10);
  EXPECT_NEAR(w.lo, 0.0, 1e-15);
  EXPECT_NEAR(w.hi, 0.2775328, 1e-6);
  const Interval h = wilson_ci95(5, 10);
  EXPECT_NEAR(h.lo, 0.2365931, 1e-6);
  EXPECT_NEAR(h.hi, 0.7634069, 1e-6);
  EXPECT_NEAR(pearson({1, 2, 3, 4}, {3, 5, 7, 9}), 1.0, 1e-15);
  EXPECT_NEAR(pearson({1, 2, 3, 4}, {4, 3, 2, 1}), -1.0, 1e-15);
  EXPECT_TRUE(std::isnan(pearson({1, 1, 1}, {1, 2, 3})));
  EXPECT_DOUBLE_EQ(mid_percentile({1, 2, 3, 4}, 2.5), 0.5);
  EXPECT_DOUBLE_EQ(mid_percentile({1, 2, 3, 4}, 2.0), 0.375);
  EXPECT_DOUBLE_EQ(mid_percentile({1, 2, 3, 4}, 9.0), 1.0);
}

TEST(Statistics, IntervalsCoverTheirPlantedMeansNinetyFivePercentOfTheTime) {
  // n = 5 normal draws: a z interval would cover ~88%; the t interval covers 95%.
  Normal z(42);
  const int reps = 4000;
  int t_cover = 0, pi_cover = 0, welch_cover = 0;
  for (int r = 0; r < reps; ++r) {
    std::vector<double> a, b;
    for (int i = 0; i < 5; ++i) a.push_back(2.0 + 0.5 * z());
    const Summary s = summarize(a);
    t_cover += s.ci95.contains(2.0);
    pi_cover += s.pi95.contains(2.0 + 0.5 * z());
    for (int i = 0; i < 12; ++i) b.push_back(1.0 + 2.0 * z());  // other size and variance
    const Summary sb = summarize(b);
    welch_cover += welch_ci95(s.mean, s.se, s.n, sb.mean, sb.se, sb.n).contains(1.0);
  }
  // Binomial(4000, 0.95) has sd 0.0034: +-0.012 is 3.5 sd.
  EXPECT_NEAR(static_cast<double>(t_cover) / reps, 0.95, 0.012);
  EXPECT_NEAR(static_cast<double>(pi_cover) / reps, 0.95, 0.012);
  EXPECT_NEAR(static_cast<double>(welch_cover) / reps, 0.95, 0.012);
}

}  // namespace
}  // namespace tecido::suites::self_contact
