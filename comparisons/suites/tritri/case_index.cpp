#include "comparisons/suites/tritri/case_index.h"

#include <algorithm>

namespace tecido::suites::tritri {

long family_pairs(const Settings& s, const Family& family) {
  return family.random ? s.random_pairs : s.pairs_per_family;
}

std::vector<CaseRange> case_ranges(const Settings& s, const std::vector<Family>& families) {
  std::vector<CaseRange> out;
  const long block = std::max(1L, s.block);
  for (std::size_t f = 0; f < families.size(); ++f) {
    const long n = family_pairs(s, families[f]);
    for (long first = 0; first < n; first += block) out.push_back({f, first, std::min(block, n - first)});
  }
  return out;
}

}  // namespace tecido::suites::tritri
