#pragma once
/// What the `tritri` suite runs (its own settings; the tolerance file holds only the agreement
/// bands, /tritri/<engine>_min_agreement). Printed in the report's method paragraph.
#include <cstddef>

namespace tecido::suites::tritri {

struct Settings {
  long random_pairs = 1000000;   ///< pairs of the `random` family (100000 with --quick)
  long pairs_per_family = 2000;  ///< pairs of each adversarial family (500 with --quick)
  long block = 10000;            ///< pairs per case: a case runs every engine on one block of one family
  /// Disagreements kept for the pairs file (in engine order, then family order, then pair order).
  std::size_t max_disagreements = 100000;
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.random_pairs = 100000;
    s.pairs_per_family = 500;
  }
  return s;
}

}  // namespace tecido::suites::tritri
