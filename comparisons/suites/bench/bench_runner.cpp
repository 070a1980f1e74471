#include "comparisons/suites/bench/bench_runner.h"

#include "comparisons/io/text_file.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

namespace tecido::suites::bench {

std::string without_nan(std::string text) {
  static const std::string nan = ": NaN", inf = ": inf", minus_inf = ": -inf";
  for (const std::string* bad : {&nan, &minus_inf, &inf})
    for (std::size_t at = text.find(*bad); at != std::string::npos; at = text.find(*bad, at + 2))
      if (at + bad->size() == text.size() || std::string(",}\n ]").find(text[at + bad->size()]) != std::string::npos)
        text.replace(at, bad->size(), ": null");
  return text;
}

std::string own_binary() {
  char buf[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "";
  buf[n] = 0;
  return buf;
}

std::string bench_binary() {
  const std::string self = own_binary();
  if (self.empty()) return "";
  const std::filesystem::path bin = std::filesystem::path(self).parent_path() / "tecido-bench";
  return std::filesystem::exists(bin) ? bin.string() : "";
}

BenchRun run_bench(const std::string& bin, const std::string& dir, const std::string& name, double min_time,
                   const std::string& filter, const std::string& simd, int repetitions) {
  BenchRun run;
  std::filesystem::create_directories(dir);
  const std::string json = dir + "/" + name + ".json";
  const std::string args =
      fmt::format("--benchmark_format=json --benchmark_min_time={:g}{}{}", min_time,
                  repetitions > 1 ? fmt::format(" --benchmark_repetitions={} --benchmark_report_aggregates_only=true", repetitions) : "",
                  filter.empty() ? "" : " --benchmark_filter='" + filter + "'");
  const std::string env = simd.empty() ? "" : "TECIDO_SIMD=" + simd + " ";
  run.command = env + "build/bin/tecido-bench " + args;
  const std::string cmd =
      fmt::format("{}'{}' {} --benchmark_out='{}.tmp' >/dev/null 2>'{}/{}.stderr'", env, bin, args, json, dir, name);
  if (std::system(cmd.c_str()) != 0 || !std::filesystem::exists(json + ".tmp")) {
    run.error = fmt::format("`{}` failed; see `bench/{}.stderr`", run.command, name);
    return run;
  }
  std::filesystem::rename(json + ".tmp", json);
  run.doc = io::parse_json_text(without_nan(io::read_text_file(json)), json);
  return run;
}

}  // namespace tecido::suites::bench
