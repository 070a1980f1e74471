// The ccd suite's bands decide pass or fail only: core's largest time-of-impact error on random
// motion made negative fails those checks, and the set of checks and every other verdict stay.
#include "comparisons/suites/ccd/ccd_suite.h"
#include "tests/support/band_perturbation.h"

namespace tecido::suites {
namespace {

TEST(CcdBands, AnImpossibleTimeOfImpactBandFailsItsChecksAndChangesNothingElse) {
  testing::expect_band_decides_only_pass_or_fail(&run_ccd_suite, "/ccd/core_random_max_toi_error", -1.0);
}

}  // namespace
}  // namespace tecido::suites
