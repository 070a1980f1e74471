#pragma once
/// The `plane` suite's report on agreement: the method paragraph (from the settings), the table of
/// every engine on every category, conclusions derived from that table, and the disagreement
/// file's paragraph. The contact-time and drop sections are contact_time_report.h and drop_report.h.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/plane/group_tally.h"
#include "comparisons/suites/plane/settings.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::plane {

/// Counts, block size, seed, referee, what each category claims and how groups are checked.
std::string method_markdown(const Settings& s, std::uint64_t seed, const std::string& referee,
                            const std::vector<Category>& categories);
/// One row per engine and category: cases, agree, false hits, misses, no answer, both hit, max t
/// error ("–" when no case where both hit), ns per case on the random row; the referee's hits per
/// category above. A category whose cases failed shows "failed" and its reason below.
std::string agreement_table(const std::vector<Category>& categories, const AgreementTable& table);

/// Per engine, what is checked and where it disagrees with the referee, read from `table` (no
/// timing, so that a merged report's prose equals the unsharded run's).
std::string agreement_conclusions(const std::vector<Category>& categories, const AgreementTable& table,
                                  const std::string& referee);

/// Where the disagreements went: `kept` of `found` cases in `file`, and the command that reruns them.
std::string disagreements_markdown(std::size_t kept, long found, const std::string& file);

/// report.json's data: {engine: {"ns_per_case", category: {"cases", "agree", "false_hits", "misses",
/// "null", "both_hit", "max_t_error" (null when none), "exact_path"}}}.
io::Json agreement_json(const std::vector<Category>& categories, const AgreementTable& table);

}  // namespace tecido::suites::plane
