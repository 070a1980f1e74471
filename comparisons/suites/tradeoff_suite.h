#pragma once
/// TEMPORARY, to be deleted at integration: the tradeoff suite moved to comparisons/suites/tradeoff/.
/// This header only keeps the old names in tecido::suites for the old copies of the ParetoFront,
/// Distances and TradeoffEngines tests (tests/comparisons/suites/test_stability_suite.cpp, renamed
/// test_tradeoff_pieces.cpp on another branch); their new copies live in
/// tests/comparisons/suites/tradeoff/. Delete this file together with the old copies.
#include "comparisons/suites/tradeoff/curtain.h"
#include "comparisons/suites/tradeoff/distances.h"
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/pareto.h"
#include "comparisons/suites/tradeoff/theory.h"
#include "comparisons/suites/tradeoff/tradeoff_suite.h"

namespace tecido::suites {
using tradeoff::CostError;
using tradeoff::hanging_cloth;
using tradeoff::max_abs_difference;
using tradeoff::omega_bound;
using tradeoff::pareto_front;
using tradeoff::rms_distance;
using tradeoff::tradeoff_engines;
using tradeoff::TradeoffEngine;
}  // namespace tecido::suites
