#pragma once
/// The ccd suite's report: what ran, per kind the false negatives and positives of every engine
/// on every family, the time-of-impact errors and times per query, the referee's own
/// consistency, and conclusions computed from those tables.
#include "comparisons/suites/ccd/families.h"
#include "comparisons/suites/ccd/family_statistics.h"
#include "comparisons/suites/ccd/settings.h"
#include "comparisons/suites/ccd/sheet_through_sheet.h"
#include "comparisons/suites/ccd/suite_engines.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::ccd {

/// The method paragraph, from the settings and the family table.
std::string method_markdown(const Settings& s, std::uint64_t seed);
/// The tables of one kind: results[k] belongs to families()[k]; failed[k] is the error of a
/// family whose case threw ("" otherwise); `not_modelled` names the engines that do not model the
/// kind (their cells read "not modelled", and a line says "not modelled by <engine>").
std::string kind_tables(CcdKind kind, const std::vector<FamilyResult>& results, const std::vector<std::string>& failed,
                        const std::vector<std::string>& not_modelled = {});
/// The outside engines among `engines`, with their doors and what is checked of them ("" when none).
std::string outside_markdown(const std::vector<SuiteEngine>& engines);
/// The referee's consistency table (constructed answers, filter) over every family.
std::string referee_table(const std::vector<FamilyResult>& results, const std::vector<std::string>& failed);
/// Conclusions drawn from the tables: who missed contacts where, false positive shares, and the
/// time per query over the suite's mix (every family weighted by its queries).
std::string conclusions(const std::vector<FamilyResult>& results, const std::vector<std::string>& failed);
/// The sheet-through-sheet case group's table and what it shows.
std::string sheet_markdown(const SheetResult& r, const SheetSettings& s);
/// report.json's data: per family, the referee's counts and each engine's figures.
io::Json results_json(const std::vector<FamilyResult>& results);

}  // namespace tecido::suites::ccd
