#include "comparisons/suites/bench/process_cost.h"

#include "comparisons/io/provenance.h"
#include "comparisons/io/text_file.h"
#include "comparisons/suites/bench/folding_cloth.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sys/resource.h>

namespace tecido::suites::bench {

namespace {
struct ProcessCommand {
  std::string name;
  std::vector<std::string> args;  ///< after the binary
  std::string out;                ///< its stdout file
  std::vector<double> cpu_ns, wall_ns;
};

double children_cpu_ns() {
  rusage u{};
  ::getrusage(RUSAGE_CHILDREN, &u);
  const auto ns = [](const timeval& t) { return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_usec) * 1e3; };
  return ns(u.ru_utime) + ns(u.ru_stime);
}

/// Runs one command; false when it fails.
bool run_timed(const std::string& tecido, const std::string& dir, ProcessCommand& c) {
  std::vector<std::string> argv{tecido};
  argv.insert(argv.end(), c.args.begin(), c.args.end());
  const std::string cmd = io::shell_line(argv) + " >" + io::shell_line({c.out}) + " 2>" + io::shell_line({dir + "/selfcollide.stderr"});
  const double cpu0 = children_cpu_ns();
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = std::system(cmd.c_str());
  c.wall_ns.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count());
  c.cpu_ns.push_back(children_cpu_ns() - cpu0);
  return rc == 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::vector<ProcessCommand> commands_of(const FoldingFiles& f, const std::string& dir, int n, const std::vector<int>& threads) {
  std::vector<ProcessCommand> cs;
  cs.push_back({fmt::format("process/selfcollide/discrete/{}", n), {"selfcollide", "--mesh", f.end, "--json"},
                dir + "/discrete.out", {}, {}});
  for (int t : threads)
    cs.push_back({fmt::format("process/selfcollide/continuous/threads:{}/{}", t, n),
                  {"selfcollide", "--mesh", f.start, "--to", f.end, "--threads", std::to_string(t), "--json"},
                  fmt::format("{}/continuous-{}.out", dir, t), {}, {}});
  return cs;
}
}  // namespace

ProcessRun time_selfcollide(const std::string& tecido, const std::string& dir, int n, int rounds, const std::vector<int>& threads) {
  ProcessRun run;
  const FoldingStep step = folding_cloth_step(n);
  const FoldingFiles files = write_folding_step(step, n, dir);
  std::vector<ProcessCommand> cs = commands_of(files, dir, n, threads);
  for (const auto& c : cs) run.commands.push_back("build/bin/tecido " + io::shell_line(c.args));
  for (int r = 0; r < rounds; ++r)
    for (std::size_t k = 0; k < cs.size(); ++k) {
      ProcessCommand& c = cs[(k + static_cast<std::size_t>(r)) % cs.size()];
      if (!run_timed(tecido, dir, c)) {
        run.error = fmt::format("`{} {}` failed; see `bench/selfcollide.stderr`", tecido, io::shell_line(c.args));
        return run;
      }
    }
  const std::string reference = cs.size() > 1 ? io::read_text_file(cs[1].out) : "";
  for (std::size_t k = 0; k < cs.size(); ++k) {
    BenchRow row;
    row.name = cs[k].name;
    row.ns_per_iter = median(cs[k].cpu_ns);
    row.real_ns_per_iter = median(cs[k].wall_ns);
    row.counters["triangles"] = static_cast<double>(step.triangles.size());
    row.counters["rounds"] = rounds;
    if (k > 0) row.counters["same_answer"] = io::read_text_file(cs[k].out) == reference ? 1 : 0;
    run.rows.push_back(std::move(row));
  }
  for (const auto& c : cs) std::filesystem::remove(c.out);
  return run;
}

}  // namespace tecido::suites::bench
