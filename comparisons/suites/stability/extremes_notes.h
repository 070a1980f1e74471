#pragma once
/// The notes under the `stability` suite's extremes table: what each group shows and why, with every
/// figure computed in the run (from the settings, the theory or the group's data) and each stated
/// outcome derived from that data. A group that failed has no data; its note says so.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/stability/extremes.h"
#include "comparisons/suites/stability/settings.h"

#include <string>

namespace tecido::suites::stability {

/// `data` is the suite's report data (the keys "offset", "mass_ratio", "near_zero", "resting",
/// "tunnelling" that the groups write).
std::string offset_note(const Settings& s, const io::Json& data, const VerdictBands& bands);
std::string mass_ratio_note(const Settings& s, const io::Json& data);
std::string near_zero_note(const Settings& s, const io::Json& data);
std::string resting_note(const Settings& s, const io::Json& data);
std::string tunnelling_note(const Settings& s, const io::Json& data);

/// The five notes, in the groups' order.
std::string extremes_notes(const Settings& s, const io::Json& data, const VerdictBands& bands);

}  // namespace tecido::suites::stability
