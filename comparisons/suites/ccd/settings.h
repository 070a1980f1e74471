#pragma once
/// What the `ccd` suite runs (its own settings; the tolerance file holds only the bands of its
/// checks, section "ccd"). Printed in the report.
#include <cstddef>
#include <vector>

namespace tecido::suites::ccd {

struct Settings {
  /// Queries of each constructed family (one case per family).
  std::size_t per_family = 4000;
  /// Queries of each random family: more, since few random queries are contacts (about one in
  /// twenty vertex-face, one in eight edge-edge) and the references' checks are rates over them.
  std::size_t random_per_family = 20000;
  /// The first this many queries of each family are also answered by the exact referee without
  /// its floating-point filter (exact_ccd_unfiltered), which must agree bit for bit.
  std::size_t unfiltered_per_family = 200;
  /// At most this many disagreements with the referee go to ccd/disagreements.json.
  std::size_t max_disagreements = 20000;
  /// Random motion: half the queries move every point anywhere in the unit cube (large
  /// motion), half by at most this much per axis (the size of a cloth's step).
  double small_motion = 0.1;
  /// Scale family: constructed contacts multiplied by 2^e (exact), e from this list in turn ...
  std::vector<int> scale_exponents = {-1000, -600, -300, -60, -20, 20, 60, 300, 600, 1000};
  /// ... or moved by +-2^k along each axis (exact while the coordinates fit in 53 bits).
  std::vector<int> offset_exponents = {10, 20, 30, 39};
  /// Near misses (and near hits) of a contact at 1 m by k units of 2^-52 m, k from this list.
  std::vector<int> near_miss_ulps = {1, 2, 3, 4};
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.per_family = 600;
    s.random_per_family = 3000;
    s.unfiltered_per_family = 60;
  }
  return s;
}

}  // namespace tecido::suites::ccd
