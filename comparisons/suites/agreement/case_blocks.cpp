#include "comparisons/suites/agreement/case_blocks.h"

#include <algorithm>

namespace tecido::suites::agreement {

std::vector<CaseRange> case_ranges(const std::vector<long>& sizes, long block) {
  std::vector<CaseRange> out;
  const long b = std::max(1L, block);
  for (std::size_t f = 0; f < sizes.size(); ++f)
    for (long first = 0; first < sizes[f]; first += b) out.push_back({f, first, std::min(b, sizes[f] - first)});
  return out;
}

}  // namespace tecido::suites::agreement
