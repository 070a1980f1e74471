#include "comparisons/suites/report_html.h"

#include <gtest/gtest.h>

namespace tecido::suites {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

std::vector<SuiteResult> two_suites() {
  SuiteResult a;
  a.name = "plane";
  a.checks = {make_check("plane/ok", 1.0, 0.0, 2.0), make_check("plane/<img src=x onerror=alert(1)>", 5.0, 0.0, 2.0),
              make_check("plane/third", 0.5, 0.0, 1.0, "a note & more")};
  a.markdown = "### Agreement\n\n| engine | misses |\n|---|---:|\n| core | 0 |\n\n![plot](plane/plot.svg)\n";
  a.views = {{"plane: 2 disagreements", "plane/disagreements.html"}, {"id <b>", "plane/disagreements.html#1"},
             {"bad", "javascript:alert(1)"}};
  SuiteResult b;
  b.name = "tritri";
  b.checks = {make_check("tritri/x", 0.0, 0.0, 0.0)};
  return {a, b};
}

TEST(ReportHtml, OneRowPerCheckFailingOnesMarked) {
  SuiteContext ctx;
  const std::string h = report_html(two_suites(), ctx);
  EXPECT_EQ(count(h, "<tr class=\"check "), 4u);
  EXPECT_EQ(count(h, "<tr class=\"check fail\""), 1u);
  EXPECT_NE(h.find("<section id=\"suite-plane\">"), std::string::npos);
  EXPECT_NE(h.find("<section id=\"suite-tritri\">"), std::string::npos);
  EXPECT_NE(h.find("<a href=\"#suite-tritri\">"), std::string::npos);
  EXPECT_NE(h.find("3 checks passed, 1 failed"), std::string::npos);
}

TEST(ReportHtml, UserTextIsEscapedAndNoScriptRuns) {
  SuiteContext ctx;
  const std::string h = report_html(two_suites(), ctx);
  EXPECT_EQ(h.find("<img src=x"), std::string::npos);
  EXPECT_NE(h.find("plane/&lt;img src=x onerror=alert(1)&gt;"), std::string::npos);
  EXPECT_NE(h.find("a note &amp; more"), std::string::npos);
  EXPECT_EQ(h.find("javascript:"), std::string::npos);
  EXPECT_EQ(h.find("<script"), std::string::npos);
  EXPECT_NE(h.find("script-src 'none'"), std::string::npos);
}

TEST(ReportHtml, SectionsCarryTheirMarkdownAndViews) {
  SuiteContext ctx;
  const std::string h = report_html(two_suites(), ctx);
  EXPECT_NE(h.find("<h3>Agreement</h3>"), std::string::npos);
  EXPECT_NE(h.find("<td class=\"num\">0</td>"), std::string::npos);
  EXPECT_NE(h.find("<img src=\"plane/plot.svg\" alt=\"plot\">"), std::string::npos);
  EXPECT_NE(h.find("<a href=\"plane/disagreements.html#1\">id &lt;b&gt;</a>"), std::string::npos);
}

}  // namespace
}  // namespace tecido::suites
