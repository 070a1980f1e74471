// Running tecido-bench (comparisons/suites/bench/bench_runner.*), with a stand-in script in its
// place: the arguments and TECIDO_SIMD reach it, its JSON is read back, a failure is reported.
#include "comparisons/suites/bench/bench_runner.h"

#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace tecido::suites::bench {
namespace {

/// A stand-in for tecido-bench that writes its arguments and TECIDO_SIMD as the JSON document.
const char* kFake = R"(#!/bin/sh
for a in "$@"; do case "$a" in --benchmark_out=*) out="${a#--benchmark_out=}";; esac; done
printf '{"simd":"%s","args":"%s","benchmarks":[]}' "$TECIDO_SIMD" "$*" > "$out"
)";

TEST(BenchRunner, PassesTheArgumentsAndTheKernelChoice) {
  const auto dir = testing::temp_dir("bench-runner");
  const auto fake = dir / "fake-bench";
  testing::write_text(fake, kFake);
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const BenchRun run = run_bench(fake.string(), (dir / "out").string(), "x", 0.25, "BM_ClothStep/", "sse2");
  ASSERT_TRUE(run.error.empty()) << run.error;
  EXPECT_EQ(run.doc["simd"], "sse2");
  const std::string args = run.doc["args"];
  EXPECT_NE(args.find("--benchmark_min_time=0.25"), std::string::npos) << args;
  EXPECT_NE(args.find("--benchmark_filter=BM_ClothStep/"), std::string::npos) << args;
  EXPECT_NE(args.find("--benchmark_format=json"), std::string::npos) << args;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "x.json"));
  EXPECT_EQ(run.command,
            "TECIDO_SIMD=sse2 build/bin/tecido-bench --benchmark_format=json --benchmark_min_time=0.25 "
            "--benchmark_filter='BM_ClothStep/'");
  const BenchRun plain = run_bench(fake.string(), (dir / "out").string(), "y", 0.25);
  EXPECT_EQ(plain.doc["simd"], "") << "TECIDO_SIMD is not set unless asked for";
  EXPECT_EQ(plain.doc["args"].get<std::string>().find("repetitions"), std::string::npos) << "one measurement unless asked for";
  const BenchRun repeated = run_bench(fake.string(), (dir / "out").string(), "r", 0.25, "", "", 3);
  EXPECT_EQ(repeated.command,
            "build/bin/tecido-bench --benchmark_format=json --benchmark_min_time=0.25 --benchmark_repetitions=3 "
            "--benchmark_report_aggregates_only=true");
  testing::write_text(fake, "#!/bin/sh\nexit 3\n");
  const BenchRun bad = run_bench(fake.string(), (dir / "out").string(), "z", 0.25);
  EXPECT_NE(bad.error.find("failed; see `bench/z.stderr`"), std::string::npos) << bad.error;
  std::filesystem::remove_all(dir);
}

TEST(BenchRunner, NonNumbersBecomeNull) {
  EXPECT_EQ(without_nan(R"({"a": NaN, "b": inf,"c": -inf}
)"), R"({"a": null, "b": null,"c": null}
)");
  EXPECT_EQ(without_nan(R"({"name": "x: NaNa", "v": 1})"), R"({"name": "x: NaNa", "v": 1})") << "only whole values";
  EXPECT_EQ(without_nan(R"({"v": NaN})"), R"({"v": null})");
}

}  // namespace
}  // namespace tecido::suites::bench
