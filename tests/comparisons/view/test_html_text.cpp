#include "comparisons/view/html_text.h"

#include <gtest/gtest.h>

namespace tecido::view {
namespace {

TEST(HtmlText, MarkupBecomesText) {
  EXPECT_EQ(html_text("<img src=x onerror=alert(1)>"), "&lt;img src=x onerror=alert(1)&gt;");
  EXPECT_EQ(html_text("a & b \"c\" 'd'"), "a &amp; b &quot;c&quot; &#39;d&#39;");
}

TEST(HtmlText, ControlBytesAndBadUtf8AreShownEscaped) {
  EXPECT_EQ(html_text(std::string("a\x01" "b", 3)), "a\\x01b");
  EXPECT_EQ(html_text("\xff<"), "\\xff&lt;");
  EXPECT_EQ(html_text("caf\xc3\xa9"), "caf\xc3\xa9");  // well-formed UTF-8 stays
}

}  // namespace
}  // namespace tecido::view
