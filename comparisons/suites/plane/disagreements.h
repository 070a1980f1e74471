#pragma once
/// The `plane` suite's disagreement file: the cases on which an engine's hit differed from the
/// referee's, as a cases file (comparisons/io/plane_cases.h) that `tecido plane --cases FILE`
/// reruns with every engine.
#include "comparisons/suites/plane/agreement.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::plane {

/// The first `cap` disagreements of `table` (engine order, then case order), each case regenerated
/// from (seed, category, k), with ids "<engine>:<category>/<k>".
std::vector<io::PlaneCase> disagreement_cases(std::uint64_t seed, const std::vector<Category>& categories,
                                              const AgreementTable& table, std::size_t cap);

/// Disagreements found, whether kept or not: false hits and misses over every engine and category.
long disagreements_found(const AgreementTable& table);

/// Writes `cases` to `path` (atomically).
void write_disagreements(const std::string& path, const std::vector<io::PlaneCase>& cases);

}  // namespace tecido::suites::plane
