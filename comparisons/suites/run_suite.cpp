#include "comparisons/suites/suite.h"

#include <chrono>

namespace tecido::suites {

SuiteResult run_suite(const SuiteEntry& entry, const SuiteContext& ctx) {
  const auto t0 = std::chrono::steady_clock::now();
  SuiteResult r = entry.run(ctx);
  r.name = entry.name;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace tecido::suites
