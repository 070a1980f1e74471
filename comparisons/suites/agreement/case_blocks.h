#pragma once
/// How an agreement suite's cases are cut into sweep cases: family by family (in table order), each
/// family in blocks of at most `block` cases, the last block shorter. A sweep case therefore feeds
/// the checks of exactly one family, and a sweep case that throws fails that family's checks only.
#include <cstddef>
#include <vector>

namespace tecido::suites::agreement {

/// Cases [first, first + count) of family `family` (an index into the family table).
struct CaseRange {
  std::size_t family = 0;
  long first = 0;
  long count = 0;
};

/// How many cases each family has: `random` for the random family, `per_family` for the others.
template <class FamilyT>
std::vector<long> family_sizes(const std::vector<FamilyT>& families, long random, long per_family) {
  std::vector<long> sizes;
  for (const FamilyT& f : families) sizes.push_back(f.random ? random : per_family);
  return sizes;
}

/// Every block, family-major, blocks in case order (`block` below 1 counts as 1). Together they
/// cover each case of each family exactly once; a family of no case has no block.
std::vector<CaseRange> case_ranges(const std::vector<long>& sizes, long block);

}  // namespace tecido::suites::agreement
