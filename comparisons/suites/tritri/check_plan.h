#pragma once
/// Which agreements the `tritri` suite checks, declared before any case runs: the names and bands
/// depend on the family table, the registered engines and the tolerance file's bands, never on
/// what the cases measure.
#include "comparisons/suites/check.h"
#include "comparisons/suites/tritri/families.h"

#include <string>
#include <vector>

namespace tecido::suites::tritri {

/// What is checked for one engine.
enum class CheckScope {
  EveryFamily,  ///< `core`: built on exact predicates, so it must agree on every pair of every family
  RandomOnly,   ///< reference engines: checked on the random family; their adversarial rows are reported
  Reported,     ///< the seed's own tests (`core-rotation`, `core-mt`), kept as written, and the referee itself
  /// An outside engine (--plugin, --engine-cmd): a triangle test offered for validation is checked
  /// on every family, against /tritri/outside_min_agreement, so a test that misses touching pairs fails.
  Outside,
};

/// The scope of `engine` when `referee` is the exact referee's name; `outside` for an engine from
/// outside tecido's tree.
CheckScope check_scope(const std::string& engine, const std::string& referee, bool outside = false);

/// The tolerance-file pointer of an engine's band: /tritri/<engine>_min_agreement, or
/// /tritri/outside_min_agreement for an outside engine (its name is the user's, not the file's).
std::string tolerance_key(const std::string& engine, CheckScope scope);

/// Whether an engine of scope `scope` is checked on `family`.
bool is_checked(CheckScope scope, const Family& family);

/// "tritri/<engine>/agreement/<family>"
std::string check_name(const std::string& engine, const std::string& family);

/// Every check, in engine order then family order: the share of pairs on which the engine agrees
/// with the referee, at least the band of tolerance_key() (io::InputError when the tolerance file
/// lacks it), at most 1. `outside` names the outside engines among `engines`.
CheckList declare_checks(const std::vector<Family>& families, const std::vector<std::string>& engines,
                         const std::string& referee, const Tolerances& tol,
                         const std::vector<std::string>& outside = {});

}  // namespace tecido::suites::tritri
