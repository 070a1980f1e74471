// tecido run SCENE.json [--integrator X] [--dt H] [--steps N] [--json] [--out DIR]
//                       [--frame-every K] [--vtk]
// With --out DIR: DIR/result.json, the frames DIR/frames/frame_<step>.obj (every K-th step,
// the first and the last; default K = ceil(steps / 100)), .vtk as well with --vtk, and
// DIR/cloth.svg, four key frames drawn by gnuplot (skipped, with a note, without gnuplot).
// A scene with `self_collision` runs with its post-step hook; the result then carries
// "self_collision": {checks, contact_checks, pairs, ...}. Obstacles are drawn into every frame at
// that frame's time (moving ones move).
#include "comparisons/cli/commands.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/cloth_plot.h"
#include "comparisons/io/frame_writer.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/run_result.h"
#include "comparisons/io/scene_json.h"
#include "core/cloth/self_collision_response.h"
#include "core/dynamics/simulation.h"

#include <algorithm>
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
    long long frame_every = 0;
    bool json = false, vtk = false;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("run", "Simulate a scene with the core engine");
  sub->add_option("scene", o->scene, "Scene file (JSON)")->required();
  sub->add_option("--integrator", o->integrator, "euler | symplectic | midpoint | rk4 (overrides the scene)");
  sub->add_option("--dt", o->dt, "Step [s] (overrides the scene)");
  sub->add_option("--steps", o->steps, "Number of steps (overrides the scene)");
  sub->add_flag("--json", o->json, "Print the result as one JSON object");
  sub->add_option("--out", o->out, "Directory for result.json, frames/ (OBJ per frame) and cloth.svg");
  sub->add_option("--frame-every", o->frame_every, "With --out: write every K-th step's frame (default: about 100 frames)");
  sub->add_flag("--vtk", o->vtk, "With --out: write legacy VTK frames as well as OBJ");
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
    if (o->frame_every < 0) throw io::UsageError("--frame-every must be >= 1");
    Simulation sim(scene);
    const auto self_collision = install_self_collision(sim);
    std::string plot_note;
    bool plotted = false;
    std::unique_ptr<io::FrameWriter> frames;
    if (o->out.empty()) {
      sim.run(scene.steps);
    } else {
      const long long every = o->frame_every > 0 ? o->frame_every : std::max(1LL, (scene.steps + 99) / 100);
      frames = std::make_unique<io::FrameWriter>(o->out + "/frames", true, o->vtk);
      // Key frames for the picture: the start, one and two thirds, the end.
      const long long n = scene.steps;
      const long long keys[4] = {0, n / 3, (2 * n) / 3, n};
      std::vector<io::PlotFrame> key_frames;
      auto capture = [&](const Simulation& s) {
        const long long k = s.steps_done();
        const Particles& p = s.particles();
        if (k % every == 0 || k == n)
          frames->write(k, s.time(), p.x, p.v, scene.triangles, io::obstacle_surfaces(scene.obstacles, s.time()));
        for (long long key : keys)
          if (k == key && (key_frames.empty() || key_frames.back().step != k)) {
            key_frames.push_back({k, s.time(), p.x});
            break;
          }
      };
      capture(sim);
      sim.run(scene.steps, capture);
      if (sim.instability() && (key_frames.empty() || key_frames.back().step != sim.steps_done()))
        capture(sim);  // the last state reached (skipped if not finite)
      plotted = io::plot_cloth_frames(o->out, "cloth", "tecido run " + o->scene, key_frames, scene.triangles,
                                      scene.forces.gravity, &plot_note);
    }
    io::Json result = io::run_result_json(sim);
    if (self_collision) {
      const SelfCollisionStats& st = self_collision->stats();
      result["self_collision"] = {{"response", self_collision_response_name(self_collision->settings().response)},
                                  {"checks", st.checks},
                                  {"contact_checks", st.contact_checks},
                                  {"share", st.checks ? static_cast<double>(st.contact_checks) / st.checks : 0.0},
                                  {"pairs", st.pairs},
                                  {"max_pairs", st.max_pairs},
                                  {"pairs_now", st.last_pairs},
                                  {"gia_regions", st.gia_regions},
                                  {"gia_failed_checks", st.gia_failed_checks},
                                  {"gia_unresolved_pairs", st.gia_unresolved_pairs},
                                  {"unseparated_cut_edges", st.unseparated_cut_edges},
                                  {"pushed_particles", st.pushed_particles}};
    }
    if (!o->out.empty()) io::write_file_atomic(o->out + "/result.json", result.dump(2) + "\n");
    if (o->json) {
      if (frames && !plotted) std::cerr << "tecido: note: " << plot_note << "\n";
      std::cout << result.dump() << "\n";
    } else {
      std::cout << "status " << result["status"].get<std::string>() << ", " << sim.steps_done() << " steps, t = "
                << sim.time() << " s, integrator " << integrator_name(scene.integrator) << "\n";
      if (sim.instability())
        std::cout << "unstable at step " << sim.instability()->step << ": particle " << sim.instability()->particle
                  << " " << sim.instability()->quantity << " is not finite\n";
      if (self_collision)
        std::cout << "self-collision (" << self_collision_response_name(self_collision->settings().response)
                  << "): contact after " << self_collision->stats().contact_checks << " of "
                  << self_collision->stats().checks << " checks\n";
      if (frames)
        std::cout << frames->written() << " frames in " << frames->dir() << "; "
                  << (plotted ? "picture " + o->out + "/cloth.svg" : plot_note) << "\n";
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
