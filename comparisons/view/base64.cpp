#include "comparisons/view/base64.h"

#include <cstring>

namespace tecido::view {

std::string base64(const unsigned char* bytes, std::size_t n) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((n + 2) / 3 * 4);
  for (std::size_t i = 0; i < n; i += 3) {
    const std::uint32_t b0 = bytes[i], b1 = i + 1 < n ? bytes[i + 1] : 0, b2 = i + 2 < n ? bytes[i + 2] : 0;
    const std::uint32_t w = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(w >> 18) & 63];
    out += kAlphabet[(w >> 12) & 63];
    out += i + 1 < n ? kAlphabet[(w >> 6) & 63] : '=';
    out += i + 2 < n ? kAlphabet[w & 63] : '=';
  }
  return out;
}

namespace {

/// The values' 32-bit patterns, least significant byte first.
std::string little_endian_base64(const std::vector<std::uint32_t>& words) {
  std::vector<unsigned char> bytes(words.size() * 4);
  for (std::size_t k = 0; k < words.size(); ++k)
    for (int b = 0; b < 4; ++b) bytes[4 * k + b] = static_cast<unsigned char>(words[k] >> (8 * b));
  return base64(bytes.data(), bytes.size());
}

}  // namespace

std::string float32_base64(const std::vector<float>& values) {
  std::vector<std::uint32_t> words(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) std::memcpy(&words[k], &values[k], 4);
  return little_endian_base64(words);
}

std::string uint32_base64(const std::vector<std::uint32_t>& values) { return little_endian_base64(values); }

}  // namespace tecido::view
