#pragma once
/// Arrays for the pages' data files (view_page.h): little-endian float32 and uint32 values packed
/// as base64 (RFC 4648, with padding), 4 bytes per value, a third of the size of decimal text and
/// decoded by the page with atob() (no fetch, which Chromium refuses from file://).
#include <cstdint>
#include <string>
#include <vector>

namespace tecido::view {

/// The base64 text of `n` bytes.
std::string base64(const unsigned char* bytes, std::size_t n);

/// Each value as a little-endian IEEE float32 (rounded to nearest), then base64.
std::string float32_base64(const std::vector<float>& values);

/// Each value as a little-endian uint32, then base64.
std::string uint32_base64(const std::vector<std::uint32_t>& values);

}  // namespace tecido::view
