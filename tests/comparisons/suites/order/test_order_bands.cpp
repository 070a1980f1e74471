// The order suite's band (/order/band, the distance allowed between a fitted and a claimed order)
// decides pass or fail only: made negative, every order check fails and nothing else changes.
#include "comparisons/suites/order/order_suite.h"
#include "tests/support/band_perturbation.h"

namespace tecido::suites {
namespace {

TEST(OrderBands, AnImpossibleBandFailsTheOrderChecksAndChangesNothingElse) {
  testing::expect_band_decides_only_pass_or_fail(&run_order_suite, "/order/band", -1.0);
}

}  // namespace
}  // namespace tecido::suites
