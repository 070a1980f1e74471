#pragma once
/// The `tritri` suite's report: the method paragraph, the agreement table, conclusions derived
/// from that table, and the disagreement file's paragraph. Every number comes from the settings
/// or from the run's AgreementTable.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/agreement/table.h"
#include "comparisons/suites/tritri/families.h"
#include "comparisons/suites/tritri/settings.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::tritri {

using agreement::AgreementTable;

/// Counts, seed, referee, and what each family claims, from the settings and the family table.
std::string method_markdown(const Settings& s, std::uint64_t seed, const std::string& referee,
                            const std::vector<Family>& families);

/// The outside engines' paragraph ("" when none): they are checked on every family, and a process
/// engine's ns/pair is wall time including its door's round trips.
std::string outside_markdown(const std::vector<outside::OutsideEnginePtr>& outside);

/// One row per engine (ns per random pair; agreeing / pairs per family, with the misses, false hits
/// and unanswered pairs apart), the referee's count of intersecting pairs on top. A family whose cases failed shows "failed" and its reason below.
std::string agreement_table(const std::vector<Family>& families, const AgreementTable& table);

/// Per engine, what is checked and where it disagrees with the referee or gives no answer, read
/// from `table`. (No timing: the prose of a merged report must equal the unsharded run's.)
std::string conclusions_markdown(const std::vector<Family>& families, const AgreementTable& table,
                                 const std::string& referee, const std::vector<std::string>& outside = {});

/// Where the disagreements went: `kept` of `found` pairs in `file`, and the command that reruns them.
std::string disagreements_markdown(std::size_t kept, long found, const std::string& file);

/// report.json's data: {engine: {"ns_per_pair", family: {"agree", "pairs", "no_answer", "misses",
/// "false_hits"}}}.
io::Json table_json(const std::vector<Family>& families, const AgreementTable& table);

}  // namespace tecido::suites::tritri
