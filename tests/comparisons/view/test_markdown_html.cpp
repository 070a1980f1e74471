#include "comparisons/view/markdown_html.h"

#include <gtest/gtest.h>

namespace tecido::view {
namespace {

TEST(MarkdownHtml, HeadingsParagraphsAndInline) {
  EXPECT_EQ(markdown_html("### Results\n\nA **bold** `x < y`\nwrapped.\n"),
            "<h3>Results</h3>\n<p>A <strong>bold</strong> <code>x &lt; y</code> wrapped.</p>\n");
}

TEST(MarkdownHtml, TableWithAlignmentAndEscapedBar) {
  const std::string md = "| a | b \\| c |\n|---|---:|\n| `p|q` | 1.5 |\n";
  EXPECT_EQ(markdown_html(md),
            "<table>\n<thead><tr><th>a</th><th class=\"num\">b | c</th></tr>\n</thead>\n<tbody>\n"
            "<tr><td><code>p|q</code></td><td class=\"num\">1.5</td></tr>\n</tbody>\n</table>\n");
}

TEST(MarkdownHtml, NestedListsAndContinuation) {
  EXPECT_EQ(markdown_html("- one\n  more\n  - inner\n- two\n"),
            "<ul>\n<li>one more<ul>\n<li>inner</li>\n</ul>\n</li>\n<li>two</li>\n</ul>\n");
  EXPECT_EQ(markdown_html("1. first\n2. second\n"), "<ol>\n<li>first</li>\n<li>second</li>\n</ol>\n");
}

TEST(MarkdownHtml, ImagesAndLinks) {
  EXPECT_EQ(markdown_inline_html("![plot](bench/scaling.svg)"), "<img src=\"bench/scaling.svg\" alt=\"plot\">");
  EXPECT_EQ(markdown_inline_html("[view](ccd/disagreements.html#3)"), "<a href=\"ccd/disagreements.html#3\">view</a>");
}

TEST(MarkdownHtml, RawHtmlIsText) {
  EXPECT_EQ(markdown_html("<img src=x onerror=alert(1)>\n"), "<p>&lt;img src=x onerror=alert(1)&gt;</p>\n");
  EXPECT_EQ(markdown_html("```\n<script>alert(1)</script>\n```\n"),
            "<pre><code>&lt;script&gt;alert(1)&lt;/script&gt;\n</code></pre>\n");
}

TEST(MarkdownHtml, UnsafeTargetsStayText) {
  EXPECT_FALSE(safe_link_target("javascript:alert(1)"));
  EXPECT_FALSE(safe_link_target("data:text/html,x"));
  EXPECT_FALSE(safe_link_target("//evil.example/x"));
  EXPECT_FALSE(safe_link_target("a\" onerror=\"x"));
  EXPECT_TRUE(safe_link_target("plane/disagreements.html#0"));
  EXPECT_TRUE(safe_link_target("https://example.org/a"));
  EXPECT_EQ(markdown_inline_html("[x](javascript:alert(1))"), "[x](javascript:alert(1))");
  EXPECT_EQ(markdown_inline_html("![x](data:image/svg+xml,<svg>)"), "![x](data:image/svg+xml,&lt;svg&gt;)");
}

}  // namespace
}  // namespace tecido::view
