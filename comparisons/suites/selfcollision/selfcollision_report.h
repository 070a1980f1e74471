#pragma once
/// The `selfcollision` suite's report: the method with what each source recorded, one table of
/// every engine on every source, and conclusions derived from that table.
#include "comparisons/suites/selfcollision/selfcollision_case.h"

#include <string>
#include <vector>

namespace tecido::suites::selfcollision {

/// The frames, the truth and the measures; per source its triangles, frames, frames with a true
/// contact and true pairs (or why its case failed), all from the settings and the scores.
std::string method_markdown(const Settings& s, const std::vector<FrameSource>& sources,
                            const std::vector<SourceScore>& scores, const std::string& truth);

/// One row per engine and source: frames answered, reported, true and false positives, missed,
/// precision, recall, milliseconds (thread CPU time) per frame.
std::string score_table(const std::vector<FrameSource>& sources, const std::vector<SourceScore>& scores);

/// Per engine but the truth: whether it matches the truth pair for pair on every source, else
/// what it missed and invented where; read from the scores.
std::string conclusions_markdown(const std::vector<FrameSource>& sources, const std::vector<SourceScore>& scores,
                                 const std::string& truth);

/// report.json's data: {"sources": {source: {...}}, engine: {source: {...}}}.
io::Json scores_json(const std::vector<FrameSource>& sources, const std::vector<SourceScore>& scores);

}  // namespace tecido::suites::selfcollision
