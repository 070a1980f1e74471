#pragma once
/// An agreement suite's disagreement file: the cases on which an engine's hit differed from the
/// referee's, regenerated from (seed, family, k) and named "<engine>:<family>/<k>", in the input
/// format of the suite's query command (`tecido plane --cases`, `tecido tritri --pairs`), which
/// reruns them with every engine.
#include "comparisons/suites/agreement/table.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace tecido::suites::agreement {

/// The cases of `kept` (kept_disagreements()), each regenerate(family, k), its id prefixed with
/// "<engine>:".
template <class Case, class Regenerate>
std::vector<Case> disagreement_cases(const AgreementTable& table, const std::vector<Disagreement>& kept,
                                     Regenerate regenerate) {
  std::vector<Case> out;
  out.reserve(kept.size());
  for (const Disagreement& d : kept) {
    Case c = regenerate(d.family, d.k);
    c.id = table.engines.at(d.engine) + ":" + c.id;
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace tecido::suites::agreement
