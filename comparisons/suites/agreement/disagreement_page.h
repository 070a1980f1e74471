#pragma once
/// The 3-D view of an agreement suite's disagreement file (view/view_page.h): beside
/// OUT/<suite>/disagreements.json, disagreements.html draws one entry at a time (the page's #k
/// opens entry k): tritri's two triangles, plane's segment and bounded plane, ccd's query animated
/// over t in [0, 1] with the referee's and the engine's times of impact; selfcollision's frame with
/// the pairs an engine missed and the extra ones. The page's data is the file's document itself
/// ({"kind", "file", "doc"}), or a compact form of it (selfcollision: arrays as base64).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/suite.h"

#include <string>
#include <vector>

namespace tecido::suites::agreement {

/// How many entries report.html links one by one (the page holds them all).
constexpr std::size_t kLinkedEntries = 20;

/// Writes the page for `doc`, the file written at out_dir/`file` ("ccd/disagreements.json"), whose
/// entries are doc[list] ("pairs", "cases", "queries", "entries"); `kind` is the view ("tritri",
/// "plane", "ccd", "selfcollision"); `page_doc`, when given, is what the page gets instead of `doc`
/// (the same entries). Returns the links report.html shows: the page, then its first
/// kLinkedEntries entries.
std::vector<PageLink> write_disagreement_page(const std::string& out_dir, const std::string& file, const char* kind,
                                              const char* list, const io::Json& doc,
                                              const io::Json* page_doc = nullptr);

}  // namespace tecido::suites::agreement
