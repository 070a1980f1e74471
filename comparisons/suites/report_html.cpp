#include "comparisons/suites/report_html.h"

#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/io/provenance.h"
#include "comparisons/suites/report.h"
#include "comparisons/view/content_policy.h"
#include "comparisons/view/html_text.h"
#include "comparisons/view/markdown_html.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

namespace tecido::suites {

namespace {

using view::html_text;

/// The section's anchor: "suite-" and the name's letters, digits, '-' and '_'.
std::string anchor(const std::string& suite) {
  std::string a = "suite-";
  for (char c : suite) a += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return a;
}

std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : std::string("—"); }

std::string band(const Check& c) { return "[" + number(c.lo) + ", " + number(c.hi) + "]"; }

struct Counts {
  int passed = 0, failed = 0;
  const Check* worst = nullptr;
};

Counts counts(const SuiteResult& r) {
  Counts n;
  for (const auto& c : r.checks) {
    (c.pass ? n.passed : n.failed)++;
    if (!n.worst || check_margin(c) < check_margin(*n.worst)) n.worst = &c;
  }
  return n;
}

std::string summary_table(const std::vector<SuiteResult>& results) {
  std::string h =
      "<table class=\"summary\">\n<thead><tr><th>suite</th><th class=\"num\">passed</th><th class=\"num\">failed</th>"
      "<th>worst check</th><th class=\"num\">value</th><th>expected</th><th class=\"num\">margin</th>"
      "<th class=\"num\">time [s]</th></tr></thead>\n<tbody>\n";
  for (const auto& r : results) {
    const Counts n = counts(r);
    h += std::string("<tr") + (n.failed ? " class=\"fail\"" : "") + "><td><a href=\"#" + anchor(r.name) + "\">" +
         html_text(r.name) + "</a></td><td class=\"num\">" + std::to_string(n.passed) + "</td><td class=\"num\">" +
         std::to_string(n.failed) + "</td>";
    if (n.worst)
      h += "<td><code>" + html_text(n.worst->name) + "</code></td><td class=\"num\">" + number(n.worst->value) +
           "</td><td>" + band(*n.worst) + "</td><td class=\"num\">" + fmt::format("{:+.3f}", check_margin(*n.worst)) +
           "</td>";
    else
      h += "<td>(no checks)</td><td></td><td></td><td></td>";
    h += "<td class=\"num\">" + fmt::format("{:.1f}", r.seconds) + "</td></tr>\n";
  }
  return h + "</tbody>\n</table>\n";
}

/// Every check, failing ones first (each group in the suite's order).
std::string checks_table(const SuiteResult& r) {
  const Counts n = counts(r);
  std::string h = std::string("<details") + (n.failed ? " open" : "") + "><summary>" +
                  fmt::format("Checks: {} passed, {} failed", n.passed, n.failed) +
                  "</summary>\n<table class=\"checks\">\n<thead><tr><th>check</th><th class=\"num\">value</th>"
                  "<th>expected</th><th>result</th><th>reason or note</th></tr></thead>\n<tbody>\n";
  for (const bool failing : {true, false})
    for (const auto& c : r.checks) {
      if (c.pass == failing) continue;
      const std::string why = !c.reason.empty() ? c.reason : (!c.pass ? std::string("outside the band") : c.note);
      h += std::string("<tr class=\"check ") + (c.pass ? "pass" : "fail") + "\"><td><code>" + html_text(c.name) +
           "</code></td><td class=\"num\">" + number(c.value) + "</td><td>" + band(c) + "</td><td>" +
           (c.pass ? "<span class=\"pass\">pass</span>" : "<span class=\"fail-word\">FAIL</span>") + "</td><td>" +
           html_text(why) + "</td></tr>\n";
    }
  return h + "</tbody>\n</table>\n</details>\n";
}

std::string page_link_html(const PageLink& v) {
  return view::safe_link_target(v.href) ? "<a href=\"" + html_text(v.href) + "\">" + html_text(v.text) + "</a>"
                                        : html_text(v.text);
}

/// The suite's pages: the first link of a group is the page, the ones after it with a '#' its entries, on one line.
std::string views_list(const SuiteResult& r) {
  if (r.views.empty()) return "";
  std::string h = "<h3>3-D views</h3>\n<ul class=\"views\">\n";
  for (std::size_t k = 0; k < r.views.size();) {
    h += "<li>" + page_link_html(r.views[k]);
    const std::string page = r.views[k].href;
    std::size_t e = ++k;
    for (; e < r.views.size() && r.views[e].href.rfind(page + "#", 0) == 0; ++e)
      h += std::string(e == k ? ": " : " · ") + page_link_html(r.views[e]);
    k = e;
    h += "</li>\n";
  }
  return h + "</ul>\n";
}

std::string navigation(const std::vector<SuiteResult>& results) {
  std::string h = "<nav><a href=\"#summary\">summary</a>";
  for (const auto& r : results) h += "<a href=\"#" + anchor(r.name) + "\">" + html_text(r.name) + "</a>";
  return h + "</nav>\n";
}

}  // namespace

std::string report_html(const std::vector<SuiteResult>& results, const SuiteContext& ctx) {
  int passed = 0, failed = 0;
  for (const auto& r : results) {
    const Counts n = counts(r);
    passed += n.passed, failed += n.failed;
  }
  std::string h = "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n" +
                  view::content_policy_meta(false) +
                  "\n<title>tecido report</title>\n<link rel=\"stylesheet\" href=\"tecido.css\">\n</head>\n"
                  "<body>\n<div class=\"report\">\n" +
                  navigation(results) + "<h1 id=\"summary\">tecido report</h1>\n<p>" +
                  view::markdown_inline_html(io::provenance_markdown()) + "</p>\n";
  h += std::string("<p><span class=\"") + (failed == 0 ? "pass\">PASS" : "fail-word\">FAIL") + "</span> — " +
       fmt::format("{} checks passed, {} failed. Seed {}{}.", passed, failed, ctx.seed,
                   ctx.quick ? ", quick mode (smaller counts, same checks)" : "") +
       "</p>\n" + summary_table(results);
  h += "<p>Margin: distance of the value to the nearer end of its band, as a fraction of the band's width (negative = "
       "outside). Tolerances: <code>" +
       html_text(ctx.tolerances ? ctx.tolerances->file() : std::string("?")) + "</code>." +
       (ctx.gnuplot ? "" : " gnuplot was not found, so this report has tables but no plots.") + "</p>\n";
  if (ctx.outside) h += view::markdown_html(outside::doors_markdown(*ctx.outside));
  for (const auto& r : results)
    h += "<section id=\"" + anchor(r.name) + "\">\n<h2>" + html_text(r.name) + "</h2>\n" + checks_table(r) +
         views_list(r) + view::markdown_html(r.markdown) + "</section>\n";
  return h + "</div>\n</body>\n</html>\n";
}

}  // namespace tecido::suites
