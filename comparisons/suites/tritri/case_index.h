#pragma once
/// How the `tritri` suite's pairs are cut into cases (comparisons/suites/agreement/case_blocks.h):
/// family by family, each family in blocks of Settings::block pairs, the last block shorter.
#include "comparisons/suites/agreement/case_blocks.h"
#include "comparisons/suites/tritri/families.h"
#include "comparisons/suites/tritri/settings.h"

#include <vector>

namespace tecido::suites::tritri {

using agreement::CaseRange;

/// How many pairs `family` has under `s`.
inline long family_pairs(const Settings& s, const Family& family) {
  return family.random ? s.random_pairs : s.pairs_per_family;
}

/// Every case, in index order: family-major, blocks in pair order.
inline std::vector<CaseRange> case_ranges(const Settings& s, const std::vector<Family>& families) {
  return agreement::case_ranges(agreement::family_sizes(families, s.random_pairs, s.pairs_per_family), s.block);
}

}  // namespace tecido::suites::tritri
