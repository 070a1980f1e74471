#pragma once
/// A family of generated cases for an agreement suite (plane's categories, tritri's families): a
/// name, one line of what it claims, a generator, and whether it is the uniform random family (the
/// one whose size is the suite's random count and on which speed is timed).
///
/// Case k of a family is a pure function of (seed, family, k): the suite derives a generator from
/// them (each suite its own substream rule, fixed by the reports it already published) and
/// family_case() draws the case and names it "<family>/<k>", so any case can be regenerated alone
/// (a sweep case, the disagreement file) and no case depends on how the cases are cut into blocks.
#include "comparisons/suites/random.h"

#include <string>
#include <vector>

namespace tecido::suites::agreement {

template <class Case>
struct Family {
  /// Draws case k from its generator `r` (id left empty).
  using Generator = Case (*)(Rng& r, long k);
  std::string name;   ///< "random", "edge", ... (case ids are "<name>/<k>")
  std::string about;  ///< one line: what the family claims about its cases
  Generator make = nullptr;
  bool random = false;  ///< the uniform family: its own count, and speed is timed on it
};

/// Case k of `family` drawn from `r`, with id "<name>/<k>".
template <class Case>
Case family_case(const Family<Case>& family, Rng r, long k) {
  Case c = family.make(r, k);
  c.id = family.name + "/" + std::to_string(k);
  return c;
}

/// The families' names, in table order.
template <class Case>
std::vector<std::string> family_names(const std::vector<Family<Case>>& families) {
  std::vector<std::string> names;
  for (const Family<Case>& f : families) names.push_back(f.name);
  return names;
}

/// Whether each family is the random one, in table order.
template <class Case>
std::vector<bool> random_flags(const std::vector<Family<Case>>& families) {
  std::vector<bool> flags;
  for (const Family<Case>& f : families) flags.push_back(f.random);
  return flags;
}

}  // namespace tecido::suites::agreement
