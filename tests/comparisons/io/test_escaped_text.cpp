// Text from outside tecido shown as text: worked cases of each kind of byte (RFC 3629 for UTF-8).
#include "comparisons/io/escaped_text.h"

#include <gtest/gtest.h>

namespace tecido::io {
namespace {

TEST(EscapedText, PrintableAsciiAndUtf8StayAsTheyAre) {
  EXPECT_EQ(escaped_text("plain text, 100% {json}"), "plain text, 100% {json}");
  EXPECT_EQ(escaped_text("colis\xc3\xa3o \xe2\x80\x94 \xf0\x9f\xa7\xb5"), "colis\xc3\xa3o \xe2\x80\x94 \xf0\x9f\xa7\xb5");
}

TEST(EscapedText, ControlBytesAreEscaped) {
  EXPECT_EQ(escaped_text("a\nb\rc\td"), "a\\nb\\rc\\td");
  EXPECT_EQ(escaped_text(std::string("\x1b[2J\x07\x7f\0z", 8)), "\\x1b[2J\\x07\\x7f\\x00z");
  EXPECT_EQ(escaped_text("\xc2\x9b" "1m"), "\\xc2\\x9b1m");  // C1 control CSI (U+009B) in UTF-8
}

TEST(EscapedText, MalformedUtf8IsEscapedByteByByte) {
  EXPECT_EQ(escaped_text("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(escaped_text("\xc0\xaf"), "\\xc0\\xaf");          // overlong '/'
  EXPECT_EQ(escaped_text("\xe0\x80\xaf"), "\\xe0\\x80\\xaf");  // overlong, three bytes
  EXPECT_EQ(escaped_text("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate (U+D800)
  EXPECT_EQ(escaped_text("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(escaped_text("\xc3"), "\\xc3");                    // cut short at the end
  EXPECT_EQ(escaped_text("\xc3z"), "\\xc3z");                  // cut short by a non-continuation
  EXPECT_EQ(escaped_text("\x80"), "\\x80");                    // a lone continuation byte
}

}  // namespace
}  // namespace tecido::io
