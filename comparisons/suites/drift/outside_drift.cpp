#include "comparisons/suites/drift/outside_drift.h"

#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace tecido::suites::drift {

InvariantRun run_outside_invariants(outside::OutsideEngine& engine, const Scene& scene, const Settings& s) {
  outside::Creation c = engine.create(scene);
  if (!c.simulation) throw std::runtime_error(outside::not_modelled_line(engine.name(), c.refusal));
  InvariantTally tally(scene, s.steps);
  for (long long done = 0; done < s.steps;) {
    const long long k = std::min<long long>(s.sample_every, s.steps - done);
    if (!c.simulation->advance(k)) {
      tally.r.unstable_at_step = done + k;
      break;
    }
    done += k;
    if (done % s.sample_every == 0)
      tally.sample(done, done * scene.dt, c.simulation->positions(), c.simulation->velocities(), Vec3::Zero(),
                   done % s.plot_every == 0);
  }
  return tally.finish();
}

std::string outside_prefix(const std::string& scene, const std::string& engine) {
  return "drift/" + scene + "/" + engine + "/";
}

void declare_outside_drift(CheckList& checks, const std::vector<Conservative>& scenes,
                           const std::vector<outside::OutsideEnginePtr>& engines, const Tolerances& tol) {
  for (const auto& e : engines)
    for (const Conservative& c : scenes)
      checks.declare(outside_prefix(c.name, e->name()) + "momentum", tol.at_most("/drift/momentum_rel"),
                     "max |P(t) - P0| / max(sum m|v0|, sum m|v(t)|) (outside engine " + e->name() + ")");
}

namespace {

/// One table row, and the run's check set or failed.
std::string row(const std::string& scene, const std::string& engine, const io::Json& result, CheckList& checks) {
  const std::string check = outside_prefix(scene, engine) + "momentum";
  if (const std::string* err = case_error(result)) {
    checks.fail(check, *err);
    return fmt::format("| {} | {} | {} | | | | | |\n", scene, engine, *err);
  }
  const InvariantRun r = invariant_from_json(result);
  if (r.unstable_at_step) {
    checks.fail(check, fmt::format("unstable by step {}", r.unstable_at_step));
    return fmt::format("| {} | {} | unstable by step {} | | | | | |\n", scene, engine, r.unstable_at_step);
  }
  checks.set(check, r.momentum_error);
  return fmt::format("| {} | {} | {:.3e} | {:.3e} | {:.3e} | {:.2f} | {:.1e} | {:.1e} |\n", scene, engine,
                     r.final_rel_energy, r.max_rel_energy, r.growth_rate, r.last_over_first_half, r.momentum_error,
                     r.angular_momentum_error);
}

}  // namespace

std::string outside_drift_markdown(const std::vector<Conservative>& scenes,
                                   const std::vector<outside::OutsideEnginePtr>& engines,
                                   const std::vector<io::Json>& results, CheckList& checks, io::Json& data) {
  if (engines.empty()) return "";
  std::string md =
      "#### Outside engines\n\nThe same scenes, steps and samples as core's integrators above, stepped through each "
      "engine's door (one call per sample). Checked: momentum, as for core (central forces sum to zero); energy and "
      "angular momentum are the engine's method's business: reported beside core's, not checked.\n\n";
  for (const auto& e : engines) md += "- " + e->name() + ": " + e->door() + "\n";
  md += "\n| scene | engine | final rel. energy error | max rel. error | growth rate [1/s] | last/first half | "
        "momentum error | angular momentum error |\n|---|---|---:|---:|---:|---:|---:|---:|\n";
  std::size_t k = 0;
  for (const auto& e : engines) {
    for (const Conservative& c : scenes) {
      const io::Json& r = results.at(k++);
      md += row(c.name, e->name(), r, checks);
      io::Json d = r;
      if (d.is_object()) d.erase("energy_curve");
      data[c.name][e->name()] = d;
    }
  }
  return md + "\n";
}

}  // namespace tecido::suites::drift
