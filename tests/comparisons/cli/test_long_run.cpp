// Long runs: memory stays flat over many steps of a cloth (no per-step growth; under the asan
// preset the live heap is measured instead of RSS, and LeakSanitizer checks that nothing
// leaks), and a run killed with SIGKILL at any moment
// leaves either no report or a complete one, never a half-written report.json / result.json
// (comparisons/io/atomic_file.h: content goes to <target>.tmp.<pid>, then is renamed).
#include "tests/support/cli_runner.h"
#include "tests/support/command_line_mask.h"

#include "core/geometry/bounded_plane.h"
#include "core/scene/cloth_builder.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char** environ;

// Present (non-null) only when the AddressSanitizer / LeakSanitizer runtime is linked in.
extern "C" __attribute__((weak)) std::size_t __sanitizer_get_current_allocated_bytes();
extern "C" __attribute__((weak)) int __lsan_do_recoverable_leak_check();

namespace tecido {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// Resident set size of this process [bytes] (/proc/self/statm, second field, in pages).
long long rss_bytes() {
  std::ifstream in("/proc/self/statm");
  long long size = 0, resident = 0;
  in >> size >> resident;
  return resident * static_cast<long long>(::sysconf(_SC_PAGESIZE));
}

/// A 16 x 16 cloth (0.75 m square) hanging from its two top corners in a strong wind that
/// circles the vertical axis, with gravity, air drag, a floor it sweeps over, and
/// self-collision (GIA + edge mode 3) after every 4th step: the wind folds it onto itself, so
/// every per-step code path of a cloth run (forces, plane contacts, resting contacts,
/// detection, GIA regions, edge pushes) runs many times.
Scene windblown_cloth() {
  Scene s;
  s.integrator = IntegratorKind::Symplectic;
  s.dt = 0.002;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.forces.air_drag = 0.01;
  Wind wind;
  wind.force = Vec3(0.2, 0, 0);
  wind.swirl = true;
  wind.rate = 3.0;
  wind.axis = Vec3::UnitZ();
  s.forces.wind = wind;
  ClothGridSpec c;
  c.rows = c.cols = 16;
  c.spacing = 0.05;
  c.origin = Vec3(-0.375, 0.0, 1.0);
  c.axis_u = Vec3::UnitX();
  c.axis_v = -Vec3::UnitZ();
  c.total_mass = 0.5;
  c.stiffness_b = 20.0;
  c.stiffness_a = 4.0;
  c.damping = 0.01;
  c.elasticity = 0.3;
  c.pins = {{0, 0}, {0, 15}};
  append_cloth(s, c);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(2.0, 2.0), 0.5));
  SelfCollisionSettings sc;
  sc.response = SelfCollisionResponse::GiaEdge3;
  sc.strength = 0.01;
  sc.every = 4;
  s.self_collision = sc;
  return s;
}

TEST(LongRun, MemoryStaysFlatOverTenTimesMoreSteps) {
  const Scene scene = windblown_cloth();
  Simulation sim(scene);
  const auto hook = install_self_collision(sim);
  ASSERT_TRUE(hook);
  // Under ASan, RSS is no measure: freed blocks sit in its quarantine (up to 256 MB), so any
  // allocation per step (there is one, ~1.5 kB, while particles rest on a plane) shows as
  // growth. There the live heap, which a leak or an ever-growing buffer does increase, is used.
  const bool asan = __sanitizer_get_current_allocated_bytes != nullptr;
  auto memory = [&]() -> long long {
    return asan ? static_cast<long long>(__sanitizer_get_current_allocated_bytes()) : rss_bytes();
  };
  const long long warmup = 1000;
  ASSERT_TRUE(sim.run(warmup));
  const long long m0 = memory();
  ASSERT_TRUE(sim.run(10 * warmup)) << "unstable at step " << sim.instability()->step;
  const long long m1 = memory();
  ASSERT_GT(m0, 0);
  // The state is a few hundred kB; 1 MiB of slack absorbs allocator noise but not growth per
  // step: 10^4 steps keeping even 105 bytes each would exceed it.
  EXPECT_LE(m1 - m0, 1 << 20) << (asan ? "live heap " : "RSS ") << m0 << " -> " << m1 << " bytes over "
                              << 10 * warmup << " steps";
  if (__lsan_do_recoverable_leak_check != nullptr) {
    EXPECT_EQ(__lsan_do_recoverable_leak_check(), 0) << "LeakSanitizer found leaks (report above)";
  }
  EXPECT_EQ(sim.steps_done(), 11 * warmup);
  EXPECT_GT(hook->stats().contact_checks, 100) << "the cloth should fold onto itself: the response must run";
  std::printf("[ %s %lld -> %lld bytes over %lld steps; self-contact after %lld of %lld checks ]\n",
              asan ? "live heap" : "RSS", m0, m1, 10 * warmup, hook->stats().contact_checks, hook->stats().checks);
  // The physics went somewhere sensible: the cloth is on or above the floor, never through it.
  for (std::size_t i = 0; i < sim.particles().size(); ++i) EXPECT_GE(sim.particles().x[i].z(), -1e-9) << "particle " << i;
}

/// Starts `args` as a child process (stdout, stderr to /dev/null); returns its pid.
pid_t spawn_cli(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  std::string cli = TECIDO_CLI;
  argv.push_back(cli.data());
  std::vector<std::string> copy = args;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, cli.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  return rc == 0 ? pid : -1;
}

/// Runs to completion; returns the wall time [s] and the exit status.
double run_to_completion(const std::vector<std::string>& args, int* status) {
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = spawn_cli(args);
  if (pid < 0) return -1.0;
  ::waitpid(pid, status, 0);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Starts `args`, SIGKILLs it after `delay` seconds (if still running); true if it was killed.
bool run_and_kill(const std::vector<std::string>& args, double delay) {
  const pid_t pid = spawn_cli(args);
  if (pid < 0) return false;
  std::this_thread::sleep_for(std::chrono::duration<double>(delay));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

/// A temporary file's name: <name>.tmp.<pid> (gnuplot.cpp) or <name>.tmp.<pid>.<n> (atomic_file.cpp).
bool is_temporary_name(const std::string& name) {
  const auto at = name.rfind(".tmp.");
  if (at == std::string::npos) return false;
  const std::string rest = name.substr(at + 5);
  const auto dot = rest.find('.');
  const auto digits = [](const std::string& d) {
    return !d.empty() && d.find_first_not_of("0123456789") == std::string::npos;
  };
  return dot == std::string::npos ? digits(rest) : digits(rest.substr(0, dot)) && digits(rest.substr(dot + 1));
}

/// Files left in `dir` besides the expected ones must be temporary files (is_temporary_name).
void expect_only_known_files(const fs::path& dir, const std::vector<std::string>& finals) {
  if (!fs::exists(dir)) return;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    bool known = is_temporary_name(name);
    for (const auto& f : finals) known = known || name == f;
    const std::string ext = e.path().extension().string();
    known = known || ext == ".dat" || ext == ".gp" || ext == ".svg" || ext == ".obj" || ext == ".vtk" || ext == ".json";
    EXPECT_TRUE(known) << "unexpected file " << e.path();
  }
}

/// When to kill, as fractions of an uninterrupted run's wall time `full` [s].
std::vector<double> kill_fractions(double full) {
  if (full > 1.0) return {0.5, 0.95, 1.0};
  return {0.3, 0.7, 0.9, 0.96, 0.99, 1.0, 1.02};
}

std::string tail(const std::string& s, std::size_t n) { return s.size() <= n ? s : s.substr(s.size() - n); }

TEST(LongRun, TemporaryNamesAreThoseTheWritersMake) {
  EXPECT_TRUE(is_temporary_name("result.json.tmp.4711"));
  EXPECT_TRUE(is_temporary_name("frame_0003.obj.tmp.4711.12"));
  EXPECT_FALSE(is_temporary_name("result.json"));
  EXPECT_FALSE(is_temporary_name("result.json.tmp."));
  EXPECT_FALSE(is_temporary_name("result.json.tmp.47x1"));
  EXPECT_FALSE(is_temporary_name("result.json.tmp.4711."));
  EXPECT_FALSE(is_temporary_name("result.json.tmp.4711.1.2"));
}

TEST(LongRun, KilledSuiteLeavesNoHalfWrittenReport) {
  const auto dir = testing::temp_dir("kill-suite");
  // The reference: one complete run, and how long it takes on this machine (and build).
  const fs::path ref = dir / "ref";
  int status = 0;
  const double full = run_to_completion({"suite", "order", "--threads", "1", "--out", ref.string()}, &status);
  ASSERT_GT(full, 0.0);
  ASSERT_TRUE(WIFEXITED(status)) << "reference run did not exit";
  ASSERT_TRUE(fs::exists(ref / "report.json"));
  json ref_json = json::parse(testing::slurp(ref / "report.json"));
  ASSERT_TRUE(ref_json.contains("suites"));
  const std::string ref_md_tail = tail(testing::slurp(ref / "report.md"), 300);
  int killed = 0, absent = 0, complete = 0;
  // Kill at fractions of the full run time, dense near the end where the report is written
  // (fewer in slow builds, such as the asan preset's, where one run takes seconds).
  int attempt = 0;
  for (double f : kill_fractions(full)) {
    const fs::path out = dir / ("k" + std::to_string(attempt++));
    const bool was_killed = run_and_kill({"suite", "order", "--threads", "1", "--out", out.string()}, f * full);
    killed += was_killed ? 1 : 0;
    const fs::path report = out / "report.json";
    if (!fs::exists(report)) {
      ++absent;
    } else {
      ++complete;
      const std::string text = testing::slurp(report);
      json j;
      ASSERT_NO_THROW(j = json::parse(text)) << "partial report.json after a kill at " << f << " x run time:\n" << text;
      ASSERT_TRUE(j.contains("suites") && j["suites"].size() == ref_json["suites"].size());
      EXPECT_EQ(j["suites"][0]["checks"], ref_json["suites"][0]["checks"]);
      EXPECT_EQ(text.back(), '\n');
    }
    if (fs::exists(out / "report.md")) {
      const std::string md = testing::slurp(out / "report.md");
      EXPECT_EQ(tail(md, 300), ref_md_tail) << "report.md is not complete after a kill at " << f << " x run time";
    }
    expect_only_known_files(out, {"report.json", "report.md", "report.html", "tecido.css", "tecido-viewer.js",
                                  "disagreements.html", "disagreements.data.js"});
  }
  EXPECT_GT(killed, 0) << "no run was killed: the delays are all too long";
  std::printf("[ killed %d of %d runs; report.json absent %d, complete %d; full run %.3f s ]\n", killed,
              absent + complete, absent, complete, full);
  fs::remove_all(dir);
}

TEST(LongRun, KilledRunLeavesNoHalfWrittenResult) {
  const auto dir = testing::temp_dir("kill-run");
  // A cloth run long enough to be killed during the simulation, during the frames and at the end.
  const std::string scene = (dir / "cloth.json").string();
  testing::write_text(scene, R"({"integrator":"symplectic","dt":0.002,"steps":2000,"gravity":[0,0,-9.81],"air_drag":0.01,
    "cloth":{"rows":16,"cols":16,"spacing":0.05,"origin":[-0.375,-0.375,0.3],"axis_u":[1,0,0],"axis_v":[0,1,0],
             "total_mass":0.5,"stiffness_b":50,"stiffness_a":10,"damping":0.01,"elasticity":0.3,"pins":[[0,0]]},
    "planes":[{"position":[0,0,0],"normal":[0,0,1],"forward":[1,0,0],"half_extents":[2,2],"friction":0.5}]})");
  const fs::path ref = dir / "ref";
  int status = 0;
  const double full = run_to_completion({"run", scene, "--out", ref.string(), "--frame-every", "100"}, &status);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  // Each run records its own command line (its --out): masked.
  const std::string ref_text = testing::mask_command_line(testing::slurp(ref / "result.json"));
  ASSERT_FALSE(ref_text.empty());
  int killed = 0, runs = 0, complete = 0;
  for (double f : kill_fractions(full)) {
    const fs::path out = dir / ("k" + std::to_string(runs++));
    killed += run_and_kill({"run", scene, "--out", out.string(), "--frame-every", "100"}, f * full) ? 1 : 0;
    if (fs::exists(out / "result.json")) {
      ++complete;
      EXPECT_EQ(testing::mask_command_line(testing::slurp(out / "result.json")), ref_text) << "result.json differs after a kill at " << f << " x run time";
    }
    // Frames are written atomically too: any frame present is the complete frame.
    if (fs::exists(out / "frames")) {
      for (const auto& e : fs::directory_iterator(out / "frames")) {
        if (e.path().extension() == ".obj") {
          EXPECT_EQ(testing::slurp(e.path()), testing::slurp(ref / "frames" / e.path().filename())) << e.path();
        }
      }
    }
    expect_only_known_files(out, {"result.json", "cloth.svg", "index.html", "index.data.js", "tecido.css",
                                  "tecido-viewer.js"});
  }
  EXPECT_GT(killed, 0);
  std::printf("[ killed %d of %d runs; result.json complete in %d, absent in the others; full run %.3f s ]\n", killed,
              runs, complete, full);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tecido
