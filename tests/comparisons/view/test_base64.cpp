#include "comparisons/view/base64.h"

#include <gtest/gtest.h>

namespace tecido::view {
namespace {

std::string b64(const std::string& s) { return base64(reinterpret_cast<const unsigned char*>(s.data()), s.size()); }

// RFC 4648 section 10's test vectors.
TEST(Base64, Rfc4648Vectors) {
  EXPECT_EQ(b64(""), "");
  EXPECT_EQ(b64("f"), "Zg==");
  EXPECT_EQ(b64("fo"), "Zm8=");
  EXPECT_EQ(b64("foo"), "Zm9v");
  EXPECT_EQ(b64("foob"), "Zm9vYg==");
  EXPECT_EQ(b64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(b64("foobar"), "Zm9vYmFy");
}

// IEEE 754 binary32: 1.0f = 0x3f800000, -2.0f = 0xc0000000; little-endian bytes 00 00 80 3f, 00 00 00 c0.
TEST(Base64, Float32IsLittleEndianIeee) {
  const unsigned char bytes[] = {0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00, 0xc0};
  EXPECT_EQ(float32_base64({1.0f, -2.0f}), base64(bytes, sizeof bytes));
}

TEST(Base64, Uint32IsLittleEndian) {
  const unsigned char bytes[] = {0x04, 0x03, 0x02, 0x01, 0xff, 0x00, 0x00, 0x00};
  EXPECT_EQ(uint32_base64({0x01020304u, 255u}), base64(bytes, sizeof bytes));
}

}  // namespace
}  // namespace tecido::view
