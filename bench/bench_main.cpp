// tecido-bench's entry point: Google Benchmark's main, after refusing a TECIDO_SIMD value the CPU
// cannot run (core/platform/simd_level.h): one line on stderr, exit status 2, nothing measured.
#include "core/platform/simd_level.h"

#include <benchmark/benchmark.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (const auto& simd = tecido::simd_choice(); !simd.error.empty()) {
    std::fprintf(stderr, "tecido-bench: %s\n", simd.error.c_str());
    return 2;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
