#pragma once
// Known findings: bugs a target found that are left to their owners (core's CCD rewrite, the
// engines' door), each with its reproducer kept as a regress_* seed. A target reports them only
// when TECIDO_FUZZ_STRICT=1 is set, so that it stays useful for new findings until the fix lands;
// the fix's author runs the target with it set (the seed then fails until the bug is fixed).
#include <cstdlib>

namespace tecido::fuzz {

inline bool strict_mode() {
  static const bool strict = [] {
    const char* s = std::getenv("TECIDO_FUZZ_STRICT");
    return s != nullptr && s[0] == '1';
  }();
  return strict;
}

}  // namespace tecido::fuzz
