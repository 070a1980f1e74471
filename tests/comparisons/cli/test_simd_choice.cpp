// TECIDO_SIMD from outside (core/platform/simd_level.h): a cloth run with springs and
// self-collision prints the same bytes whatever instruction set its kernels are allowed, and a
// value the CPU cannot run, or an unknown one, ends the process with exit 2 and one line.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"

#include "core/platform/simd_level.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace tecido {
namespace {

/// `tecido ARGS` with TECIDO_SIMD set to `value` (unset when null); the test's own environment is restored.
testing::CliResult run_with_simd(const char* value, const std::string& args) {
  const char* old = std::getenv("TECIDO_SIMD");
  const std::string saved = old ? old : "";
  if (value) {
    ::setenv("TECIDO_SIMD", value, 1);
  } else {
    ::unsetenv("TECIDO_SIMD");
  }
  testing::CliResult r = testing::run_cli(args);
  if (old) {
    ::setenv("TECIDO_SIMD", saved.c_str(), 1);
  } else {
    ::unsetenv("TECIDO_SIMD");
  }
  return r;
}

TEST(SimdChoice, EveryAllowedKernelGivesTheSameBits) {
  // The seed's scene: a 16 x 16 cloth (spring kernels) with self-collision after every step
  // (the box tree's masks), 150 steps.
  const std::string args =
      std::string("run '") + TECIDO_SOURCE_DIR + "/data/scenes/seed_fig21_self_contact.json' --steps 150 --json";
  const testing::CliResult widest = run_with_simd(nullptr, args);
  ASSERT_EQ(widest.code, 0) << widest.err;
  ASSERT_NE(widest.out.find("\"particles\""), std::string::npos);
  int compared = 0;
  for (SimdLevel l : {SimdLevel::Scalar, SimdLevel::SSE2, SimdLevel::AVX, SimdLevel::AVX512}) {
    const testing::CliResult r = run_with_simd(simd_level_name(l), args);
    if (!cpu_has_simd_level(l)) {
      EXPECT_EQ(r.code, 2) << simd_level_name(l);
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_TRUE(r.out.empty());
      continue;
    }
    EXPECT_EQ(r.code, 0) << simd_level_name(l) << ": " << r.err;
    EXPECT_EQ(r.out, widest.out) << "TECIDO_SIMD=" << simd_level_name(l) << " changed the result";
    ++compared;
  }
  EXPECT_GE(compared, 1);
}

TEST(SimdChoice, AnUnknownNameIsBadUsage) {
  const testing::CliResult r = run_with_simd("avx2", "--help");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("TECIDO_SIMD=avx2: unknown instruction set (choose one of: scalar"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << "refused before any work";
}

}  // namespace
}  // namespace tecido
