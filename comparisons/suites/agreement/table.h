#pragma once
/// Everything an agreement suite's blocks measured, summed per family and engine: the referee's
/// hits, each engine's tally against it, the CPU time each engine spent on the random family, the
/// first error of a family whose block threw, and each disagreement (with both answers).
#include "comparisons/suites/agreement/tally.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tecido::suites::agreement {

struct AgreementTable {
  std::vector<std::string> engines;                 ///< in the order of the block results
  std::vector<std::string> error;                   ///< per family: the first error of one of its blocks, "" if none
  std::vector<long> hits;                           ///< per family: cases the referee says hit
  std::vector<std::vector<Tally>> tally;            ///< [family][engine]
  std::vector<double> random_seconds;               ///< per engine: thread CPU time over the random family
  std::vector<long> random_timed;                   ///< per engine: cases those seconds cover
  std::vector<std::vector<Disagreement>> disagree;  ///< per engine, in case order
};

/// An empty table for `families` x `engines`.
AgreementTable empty_table(std::size_t families, const std::vector<std::string>& engines);

/// Nanoseconds per random case of engine e (NaN when no random case was timed).
double ns_per_case(const AgreementTable& table, std::size_t e);

/// Disagreements found, whether kept or not: false hits and misses over every engine and family.
long disagreements_found(const AgreementTable& table);

/// The first `cap` disagreements of `table`: engine order, then case order.
std::vector<Disagreement> kept_disagreements(const AgreementTable& table, std::size_t cap);

}  // namespace tecido::suites::agreement
