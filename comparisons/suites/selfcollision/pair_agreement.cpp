#include "comparisons/suites/selfcollision/pair_agreement.h"

#include <algorithm>
#include <iterator>

namespace tecido::suites::selfcollision {

PairDifference pair_difference(const std::vector<std::array<int, 2>>& got, const std::vector<std::array<int, 2>>& truth) {
  PairDifference d;
  std::set_difference(truth.begin(), truth.end(), got.begin(), got.end(), std::back_inserter(d.missed));
  std::set_difference(got.begin(), got.end(), truth.begin(), truth.end(), std::back_inserter(d.extra));
  return d;
}

void PairAgreement::add(const std::vector<std::array<int, 2>>& got, const std::vector<std::array<int, 2>>& truth) {
  std::vector<std::array<int, 2>> common;
  std::set_intersection(got.begin(), got.end(), truth.begin(), truth.end(), std::back_inserter(common));
  reported += static_cast<long>(got.size());
  true_positives += static_cast<long>(common.size());
  false_positives += static_cast<long>(got.size() - common.size());
  missed += static_cast<long>(truth.size() - common.size());
}

}  // namespace tecido::suites::selfcollision
