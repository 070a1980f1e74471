#pragma once
/// The statistics the experiments share (comparisons/stats/): summaries and intervals
/// (summary.h), distribution functions (distributions.h), t and binomial tests with equivalence
/// by two one-sided tests and Wilson's interval (hypothesis_tests.h), Holm's adjustment for a
/// family of tests (holm.h), Pearson's and Spearman's correlation with Fisher's z interval
/// (rank_correlation.h). tests/comparisons/stats/test_stats.cpp checks each against worked values.
#include "comparisons/stats/distributions.h"
#include "comparisons/stats/holm.h"
#include "comparisons/stats/hypothesis_tests.h"
#include "comparisons/stats/rank_correlation.h"
#include "comparisons/stats/summary.h"
