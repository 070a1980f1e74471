// tecido run SCENE.json [--integrator X] [--dt H] [--steps N] [--json] [--out DIR]
#include "comparisons/cli/commands.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/run_result.h"
#include "comparisons/io/scene_json.h"
#include "core/dynamics/simulation.h"

#include <cmath>
#include <iostream>
#include <memory>

namespace tecido::cli {

namespace {

Command add_run(CLI::App& app) {
  struct Opts {
    std::string scene, integrator, out;
    double dt = 0.0;
    long long steps = -1;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("run", "Simulate a scene with the core engine");
  sub->add_option("scene", o->scene, "Scene file (JSON)")->required();
  sub->add_option("--integrator", o->integrator, "euler | symplectic | midpoint | rk4 (overrides the scene)");
  sub->add_option("--dt", o->dt, "Step [s] (overrides the scene)");
  sub->add_option("--steps", o->steps, "Number of steps (overrides the scene)");
  sub->add_flag("--json", o->json, "Print the result as one JSON object");
  sub->add_option("--out", o->out, "Directory for result.json");
  return [o]() {
    Scene scene = io::load_scene(o->scene);
    if (!o->integrator.empty()) {
      auto k = parse_integrator(o->integrator);
      if (!k) throw io::UsageError("--integrator: unknown integrator \"" + o->integrator + "\" (euler, symplectic, midpoint, rk4)");
      scene.integrator = *k;
    }
    if (o->dt != 0.0) {
      if (!(o->dt > 0.0) || !std::isfinite(o->dt) || o->dt > io::kMaxDt) throw io::UsageError("--dt must be in (0, 10]");
      scene.dt = o->dt;
    }
    if (o->steps >= 0) {
      if (o->steps > io::kMaxSteps) throw io::UsageError("--steps is too large");
      scene.steps = o->steps;
    } else if (o->steps != -1) {
      throw io::UsageError("--steps must be >= 0");
    }
    Simulation sim(scene);
    sim.run(scene.steps);
    const io::Json result = io::run_result_json(sim);
    if (!o->out.empty()) io::write_file_atomic(o->out + "/result.json", result.dump(2) + "\n");
    if (o->json) {
      std::cout << result.dump() << "\n";
    } else {
      std::cout << "status " << result["status"].get<std::string>() << ", " << sim.steps_done() << " steps, t = "
                << sim.time() << " s, integrator " << integrator_name(scene.integrator) << "\n";
      if (sim.instability())
        std::cout << "unstable at step " << sim.instability()->step << ": particle " << sim.instability()->particle
                  << " " << sim.instability()->quantity << " is not finite\n";
      if (sim.contacts().cap_hits > 0)
        std::cout << "warning: the contact event cap was reached in " << sim.contacts().cap_hits
                  << " steps (contacts resolved without bisection)\n";
    }
    return 0;
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(run, add_run);

}  // namespace tecido::cli
