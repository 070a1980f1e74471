#pragma once
/// The `tritri` suite's disagreement file: the pairs on which an engine disagreed with the
/// referee, as a pairs file (comparisons/io/tri_pairs.h) that `tecido tritri --pairs FILE` reruns
/// with every engine.
#include "comparisons/suites/tritri/agreement.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::tritri {

/// The first `cap` disagreements of `table` (engine order, then case order), each pair regenerated
/// from (seed, family, k), with ids "<engine>:<family>/<k>".
std::vector<io::TriPair> disagreement_pairs(std::uint64_t seed, const std::vector<Family>& families,
                                            const AgreementTable& table, std::size_t cap);

/// Disagreements found, whether kept or not: answered pairs whose answer differs from the referee's.
long disagreements_found(const AgreementTable& table);

/// Writes `pairs` to `path` (atomically).
void write_disagreements(const std::string& path, const std::vector<io::TriPair>& pairs);

}  // namespace tecido::suites::tritri
