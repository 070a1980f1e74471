#pragma once
/// Continuous collision engines, by name: a name and a function of a CcdQuery
/// (core/geometry/ccd/query.h) -> the answer, or nullopt when the engine cannot answer that kind
/// (printed as null). Adding an engine is one adapter and one line in ccd_engines.cpp;
/// `tecido ccd` and the ccd suite pick it up.
///
/// Rational queries (the benchmark's CSV): an engine with `test_rational` (exact) answers on the
/// rationals themselves; the others are given the nearest doubles (prepare_ccd_entry). A query
/// whose rationals are not all doubles is `rounded`: a floating engine then answers a slightly
/// different query, so its disagreements there are counted apart.
#include "comparisons/io/ccd_queries.h"
#include "core/geometry/ccd/query.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido {

struct CcdEngine {
  std::string name;
  /// A plain function pointer, so the benchmark and suite loops time the test, not a wrapper.
  std::optional<CcdAnswer> (*test)(const CcdQuery&);
  /// The answer on exact rational input, for engines that have one (nullptr: use `test` on the
  /// nearest doubles).
  std::optional<CcdAnswer> (*test_rational)(const reference::RationalCcdQuery&) = nullptr;
};

/// Every registered engine in a fixed order: core, then exact, fcl, bullet when the reference
/// adapters are built (bullet answers vertex-face only).
const std::vector<CcdEngine>& ccd_engines();
const CcdEngine* find_ccd_engine(const std::string& name);

/// For a rational entry (CSV): fills entry.query with the nearest doubles and returns whether
/// any coordinate was rounded. A double entry is left as it is (false). Throws io::UsageError
/// when the reference adapters are not built (rationals need the exact arithmetic there).
bool prepare_ccd_entry(io::CcdQueryEntry& entry);

/// `engine`'s answer to a prepared entry: on the rationals when the entry has them and the
/// engine answers rationals, otherwise on entry.query. nullopt also when the engine refuses the
/// query's doubles (a rational beyond the range of doubles rounds to an infinity; FCL throws on
/// it, core answers its conservative hit at 0, see core/geometry/ccd/ccd.h).
std::optional<CcdAnswer> answer_ccd_entry(const CcdEngine& engine, const io::CcdQueryEntry& entry);

}  // namespace tecido
