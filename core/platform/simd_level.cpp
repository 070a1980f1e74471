#include "core/platform/simd_level.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace tecido {

namespace {
constexpr SimdLevel kLevels[] = {SimdLevel::Scalar, SimdLevel::SSE2, SimdLevel::AVX, SimdLevel::AVX512};

/// The widest level the CPU has.
SimdLevel widest_on_cpu() {
  SimdLevel best = SimdLevel::Scalar;
  for (SimdLevel l : kLevels)
    if (cpu_has_simd_level(l)) best = l;
  return best;
}
}  // namespace

const char* simd_level_name(SimdLevel level) {
  switch (level) {
    case SimdLevel::Scalar: return "scalar";
    case SimdLevel::SSE2: return "sse2";
    case SimdLevel::AVX: return "avx";
    case SimdLevel::AVX512: return "avx512";
  }
  return "?";
}

bool cpu_has_simd_level(SimdLevel level) {
  switch (level) {
    case SimdLevel::Scalar: return true;
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    // __builtin_cpu_init: safe even when called from a static initializer, before libgcc's own.
    case SimdLevel::SSE2: return true;  // part of x86-64
    case SimdLevel::AVX: __builtin_cpu_init(); return __builtin_cpu_supports("avx");
    case SimdLevel::AVX512: __builtin_cpu_init(); return __builtin_cpu_supports("avx512f");
#endif
    default: return false;
  }
}

SimdChoice choose_simd_level(const char* request) {
  SimdChoice c;
  c.level = widest_on_cpu();
  if (request == nullptr || *request == '\0') return c;
  std::string supported;
  for (SimdLevel l : kLevels) {
    if (cpu_has_simd_level(l)) supported += std::string(supported.empty() ? "" : ", ") + simd_level_name(l);
    if (std::strcmp(request, simd_level_name(l)) != 0) continue;
    if (!cpu_has_simd_level(l)) {
      c.error = std::string("TECIDO_SIMD=") + request + ": this CPU or build cannot run " + request;
    } else {
      c.level = l;
      return c;
    }
  }
  if (c.error.empty()) c.error = std::string("TECIDO_SIMD=") + request + ": unknown instruction set";
  c.error += " (choose one of: " + supported + ")";
  return c;
}

SimdLevel simd_level() {
  static const SimdLevel level = [] {
    const SimdChoice c = choose_simd_level(std::getenv("TECIDO_SIMD"));
    if (!c.error.empty()) {
      std::fprintf(stderr, "tecido: %s\n", c.error.c_str());
      std::exit(2);
    }
    return c.level;
  }();
  return level;
}

bool simd_level_allowed(SimdLevel level) { return cpu_has_simd_level(level) && level <= simd_level(); }

namespace {
/// Reads the variable when the process starts, so a refused value ends it before any work.
[[maybe_unused]] const SimdLevel read_at_startup = simd_level();
}  // namespace

}  // namespace tecido
