#pragma once
/// report.html beside report.md and report.json (`tecido suite`, `tecido merge`): the same content
/// on one page, made from the same results rather than from report.md's text. The summary (pass and
/// fail per suite, each suite's worst check, linked to its section), the outside engines, then per
/// suite its Markdown section (view/markdown_html.h: tables, plots as images), links to its 3-D
/// views (SuiteResult::views) and every one of its checks as a table row (<tr class="check">, one
/// per check of report.json, failing ones first and marked). The page runs no script (its content
/// security policy says script-src 'none'); its one style sheet, tecido.css, is copied beside it.
#include "comparisons/suites/suite.h"

#include <string>
#include <vector>

namespace tecido::suites {

std::string report_html(const std::vector<SuiteResult>& results, const SuiteContext& ctx);

}  // namespace tecido::suites
