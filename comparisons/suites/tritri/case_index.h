#pragma once
/// How the `tritri` suite's pairs are cut into cases: family by family (in table order), each
/// family in blocks of Settings::block pairs, the last block shorter. A case therefore feeds the
/// checks of exactly one family, and a case that throws fails that family's checks only.
#include "comparisons/suites/tritri/families.h"
#include "comparisons/suites/tritri/settings.h"

#include <cstddef>
#include <vector>

namespace tecido::suites::tritri {

/// Pairs [first, first + count) of family `family` (an index into the family table).
struct CaseRange {
  std::size_t family = 0;
  long first = 0;
  long count = 0;
};

/// How many pairs `family` has under `s`.
long family_pairs(const Settings& s, const Family& family);

/// Every case, in index order: family-major, blocks in pair order. Together they cover each pair
/// of each family exactly once.
std::vector<CaseRange> case_ranges(const Settings& s, const std::vector<Family>& families);

}  // namespace tecido::suites::tritri
