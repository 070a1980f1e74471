#include "comparisons/suites/bench/bench_suite.h"
#include "comparisons/suites/drift/drift_suite.h"
#include "comparisons/suites/ccd/ccd_suite.h"
#include "comparisons/suites/order/order_suite.h"
#include "comparisons/suites/plane_suite.h"
#include "comparisons/suites/selfcollision/selfcollision_suite.h"
#include "comparisons/suites/stability/stability_suite.h"
#include "comparisons/suites/tradeoff/tradeoff_suite.h"
#include "comparisons/suites/tritri/tritri_suite.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

namespace tecido::suites {

const std::vector<SuiteEntry>& suite_registry() {
  static const std::vector<SuiteEntry> suites = {
      {"order", "observed error order of each dynamics engine on analytic problems, against the order it claims", &run_order_suite, &order_sweep},
      {"drift", "energy, momentum and angular momentum over long runs; core vs Bullet on identical cloth", &run_drift_suite, &drift_sweep},
      {"plane", "segment vs bounded plane agreement with the exact referee; bisected contact time", &run_plane_suite},
      {"tritri", "triangle-triangle engines vs the exact referee by category, ns per pair", &run_tritri_suite, &tritri_sweep},
      {"ccd", "continuous collision engines vs the exact referee by family (handcrafted kinds, random): misses, false hits, toi error, ns per query", &run_ccd_suite, &ccd_sweep},
      {"selfcollision", "self-collision pair sets per engine vs exact on recorded frames: precision, recall, time", &run_selfcollision_suite, &selfcollision_sweep},
      {"bench", "runs tecido-bench: time per pair/frame/step and ratios against the reference engines", &run_bench_suite},
      {"stability", "largest stable step per integrator vs theory; offsets, mass ratios, tiny springs, resting, tunnelling", &run_stability_suite, &stability_sweep},
      {"tradeoff", "cost against accuracy of every engine and step on hanging cloths; Pareto front", &run_tradeoff_suite, &tradeoff_sweep},
  };
  return suites;
}

}  // namespace tecido::suites
