// TECIDO_SIMD's values (core/platform/simd_level.h): each name the CPU has sets that ceiling, a
// name it lacks or an unknown one is refused with one line naming the choices, and the kernels
// the dispatch points may use follow the ceiling. That results do not depend on the choice is
// tested end to end in tests/comparisons/cli/test_simd_choice.cpp.
#include "core/platform/simd_level.h"

#include "core/dynamics/packed_springs.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace tecido {
namespace {

constexpr SimdLevel kAll[] = {SimdLevel::Scalar, SimdLevel::SSE2, SimdLevel::AVX, SimdLevel::AVX512};

TEST(SimdLevel, UnsetMeansTheWidestTheCpuHas) {
  SimdLevel widest = SimdLevel::Scalar;
  for (SimdLevel l : kAll)
    if (cpu_has_simd_level(l)) widest = l;
  for (const char* unset : {static_cast<const char*>(nullptr), ""}) {
    const SimdChoice c = choose_simd_level(unset);
    EXPECT_TRUE(c.error.empty()) << c.error;
    EXPECT_EQ(c.level, widest);
  }
  EXPECT_TRUE(cpu_has_simd_level(SimdLevel::Scalar));
#if defined(__x86_64__)
  EXPECT_TRUE(cpu_has_simd_level(SimdLevel::SSE2)) << "SSE2 is part of x86-64";
#endif
}

TEST(SimdLevel, EachNameSetsItsLevelOrIsRefused) {
  for (SimdLevel l : kAll) {
    const SimdChoice c = choose_simd_level(simd_level_name(l));
    if (cpu_has_simd_level(l)) {
      EXPECT_TRUE(c.error.empty()) << c.error;
      EXPECT_EQ(c.level, l);
    } else {
      EXPECT_NE(c.error.find(std::string("cannot run ") + simd_level_name(l)), std::string::npos) << c.error;
    }
  }
  for (const char* bad : {"AVX", "sse3", "avx2", " sse2", "512"}) {
    const SimdChoice c = choose_simd_level(bad);
    EXPECT_NE(c.error.find("unknown instruction set"), std::string::npos) << bad << ": " << c.error;
    EXPECT_NE(c.error.find("choose one of: scalar"), std::string::npos) << c.error;
    EXPECT_EQ(c.error.find('\n'), std::string::npos) << "one line";
  }
}

TEST(SimdLevel, SpringKernelsFollowTheProcessCeiling) {
  // This process's ceiling comes from the environment the test runs in (normally unset).
  const SimdLevel ceiling = simd_level();
  EXPECT_TRUE(cpu_has_simd_level(ceiling));
  const char* env = std::getenv("TECIDO_SIMD");
  if (env == nullptr || *env == '\0') {
    EXPECT_EQ(ceiling, choose_simd_level(nullptr).level);
  }
  const SpringKernel kernels[] = {SpringKernel::Scalar, SpringKernel::SSE2, SpringKernel::AVX, SpringKernel::AVX512};
  for (int i = 0; i < 4; ++i) {
    const bool allowed = i == 0 || (cpu_has_simd_level(kAll[i]) && kAll[i] <= ceiling);
    EXPECT_EQ(spring_kernel_supported(kernels[i]), allowed) << simd_level_name(kAll[i]);
    EXPECT_EQ(simd_level_allowed(kAll[i]), cpu_has_simd_level(kAll[i]) && kAll[i] <= ceiling);
  }
  EXPECT_STREQ(spring_kernel_name(best_spring_kernel()), simd_level_name(ceiling));
}

}  // namespace
}  // namespace tecido
