#pragma once
/// The 3-D view of an agreement suite's disagreement file (view/view_page.h): beside
/// OUT/<suite>/disagreements.json, disagreements.html draws one entry at a time (the page's #k
/// opens entry k): tritri's two triangles, plane's segment and bounded plane, ccd's query animated
/// over t in [0, 1] with the referee's and the engine's times of impact. The page's data is the
/// file's document itself ({"kind", "file", "doc"}).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/suite.h"

#include <string>
#include <vector>

namespace tecido::suites::agreement {

/// How many entries report.html links one by one (the page holds them all).
constexpr std::size_t kLinkedEntries = 20;

/// Writes the page for `doc`, the file written at out_dir/`file` ("ccd/disagreements.json"), whose
/// entries are doc[list] ("pairs", "cases", "queries"); `kind` is the view ("tritri", "plane",
/// "ccd"). Returns the links report.html shows: the page, then its first kLinkedEntries entries.
std::vector<PageLink> write_disagreement_page(const std::string& out_dir, const std::string& file, const char* kind,
                                              const char* list, const io::Json& doc);

}  // namespace tecido::suites::agreement
