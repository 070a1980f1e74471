// tecido run SCENE.json [--integrator X] [--dt H] [--steps N] [--json] [--out DIR]
//                       [--frame-every K] [--vtk] [--max-work W]
// With --out DIR: DIR/result.json (the --json result and "tecido": {version, commit,
// command_line}), the frames DIR/frames/frame_<step>.obj (every K-th step, the first and the
// last; default K = ceil(steps / 100); an earlier run's frames there are removed first, with a
// note on stderr, io/stale_frames.h), .vtk as well with --vtk, and DIR/cloth.svg, four key
// frames drawn by gnuplot (skipped, with a note, without gnuplot).
// A scene with `self_collision` runs with its post-step hook; the result then carries
// "self_collision": {checks, contact_checks, pairs, ...}. Obstacles are drawn into every frame at
// that frame's time (moving ones move). DIR/index.html (with index.data.js and the viewer's files)
// plays the frames in a browser: the cloth, the obstacles, the triangle pairs in self-contact and
// the springs through an obstacle at each frame (comparisons/view/run_view.h).
// A run that goes unstable is a result (exit 0); where the scene has springs, one line on stderr
// gives the step its stiffest spring allows for the integrator used (suites/stability/step_hint.h).
// Every limit is checked before the first step: the options' domains (cli/option_checks.h), the
// scene's sizes (io/scene_json.h), the work limit (io/work_limit.h), the frame count and that
// DIR can be written.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/cloth_plot.h"
#include "comparisons/io/frame_writer.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/io/provenance.h"
#include "comparisons/io/run_result.h"
#include "comparisons/io/scene_json.h"
#include "comparisons/io/stale_frames.h"
#include "comparisons/io/work_limit.h"
#include "comparisons/suites/stability/step_hint.h"
#include "comparisons/view/run_view.h"
#include "comparisons/view/view_page.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

namespace tecido::cli {

namespace {

struct RunOptions {
  std::string scene, integrator, out;
  double dt = 0.0;
  long long steps = 0;
  long long frame_every = 0;
  int threads = 1;
  double max_work = io::kDefaultMaxWork;
  bool json = false, vtk = false;
  CLI::Option *dt_opt = nullptr, *steps_opt = nullptr, *every_opt = nullptr;
};

/// The scene with the command line's overrides, once every limit is known to hold.
Scene prepared_scene(const RunOptions& o) {
  Scene scene = io::load_scene(o.scene);
  if (!o.integrator.empty()) scene.integrator = *parse_integrator(o.integrator);
  if (o.dt_opt->count() > 0) scene.dt = o.dt;
  if (o.steps_opt->count() > 0) scene.steps = o.steps;
  if (scene.self_collision)
    scene.self_collision->threads =
        o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::string too_much = io::work_limit_problem(scene, scene.steps, o.max_work);
  if (!too_much.empty()) {
    if (o.steps_opt->count() > 0) throw io::UsageError("--steps: " + too_much);
    throw io::InputError(o.scene, "/steps", too_much);
  }
  return scene;
}

/// Every K-th step of the run (K from --frame-every, or about 100 frames in all), once the
/// frames and what they hold fit their limits.
long long frame_interval(const RunOptions& o, const Scene& scene) {
  const long long steps = scene.steps;
  if (o.every_opt->count() == 0) return std::max(1LL, (steps + 99) / 100);
  const long long frames = steps / o.frame_every + 2;
  const std::string gives = "--frame-every: " + std::to_string(o.frame_every) + " gives " + std::to_string(frames) +
                            " frames of " + std::to_string(steps) + " steps";
  if (frames > io::kMaxFrames)
    throw io::UsageError(gives + ", more than the limit of " + std::to_string(io::kMaxFrames) + " (choose a larger K)");
  double elements = static_cast<double>(scene.particles.size() + scene.triangles.size());
  for (const io::SurfaceMesh& m : io::obstacle_surfaces(scene.obstacles, 0.0))  // drawn into every frame
    elements += static_cast<double>(m.vertices.size() + m.triangles.size());
  if (static_cast<double>(frames) * elements > io::kMaxFrameElements)
    throw io::UsageError(gives + " of " + std::to_string(static_cast<long long>(elements)) +
                         " particles and triangles, more than the limit of 1e9 in all (choose a larger K)");
  return o.frame_every;
}

/// Runs with frames, the key-frame picture and the page (DIR/index.html) in o.out; returns the
/// picture's note when not drawn.
std::string run_with_frames(Simulation& sim, const Scene& scene, const RunOptions& o, long long every,
                            io::FrameWriter& frames) {
  view::RunView page(scene);
  const long long page_stride = view::view_frame_stride(scene.steps, every, scene.particles.size());
  long long written = 0;
  // Key frames for the picture: the start, one and two thirds, the end.
  const long long n = scene.steps;
  const long long keys[4] = {0, n / 3, (2 * n) / 3, n};
  std::vector<io::PlotFrame> key_frames;
  auto capture = [&](const Simulation& s) {
    const long long k = s.steps_done();
    const Particles& p = s.particles();
    if ((k % every == 0 || k == n) &&
        frames.write(k, s.time(), p.x, p.v, scene.triangles, io::obstacle_surfaces(scene.obstacles, s.time())) &&
        (written++ % page_stride == 0 || k == n))
      page.add(k, s.time(), p.x);
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
  view::write_view_page(o.out, "index", "tecido run " + o.scene, page.data("tecido run " + o.scene));
  std::string note;
  const bool plotted = io::plot_cloth_frames(o.out, "cloth", "tecido run " + o.scene, key_frames, scene.triangles,
                                             scene.forces.gravity, &note);
  return plotted ? "" : note;
}

void print_summary(const Simulation& sim, const Scene& scene, const io::Json& result, const SelfCollisionResponder* sc,
                   const io::FrameWriter* frames, const RunOptions& o, const std::string& plot_note) {
  std::cout << "status " << result["status"].get<std::string>() << ", " << sim.steps_done() << " steps, t = "
            << sim.time() << " s, integrator " << integrator_name(scene.integrator) << "\n";
  if (sim.instability())
    std::cout << "unstable at step " << sim.instability()->step << ": particle " << sim.instability()->particle << " "
              << sim.instability()->quantity << " is not finite\n";
  if (sc)
    std::cout << "self-collision (" << self_collision_response_name(sc->settings().response) << "): contact after "
              << sc->stats().contact_checks << " of " << sc->stats().checks << " checks\n";
  if (frames)
    std::cout << frames->written() << " frames in " << frames->dir() << "; "
              << (plot_note.empty() ? "picture " + o.out + "/cloth.svg" : plot_note) << "\n";
  if (sim.contacts().cap_hits > 0)
    std::cout << "warning: the contact event cap was reached in " << sim.contacts().cap_hits
              << " steps (contacts resolved without bisection)\n";
}

/// Why an unstable run may have blown up, on stderr (stdout stays the result alone with --json).
void print_step_hint(const Simulation& sim, const Scene& scene) {
  if (!sim.instability()) return;
  if (const auto hint = suites::stability::stiffest_spring_step(scene))
    std::cerr << suites::stability::step_hint_line(*hint, scene) << "\n";
}

int run(const RunOptions& o) {
  const Scene scene = prepared_scene(o);
  const long long every = o.out.empty() ? 1 : frame_interval(o, scene);
  std::optional<io::OutputDirLock> out_lock;  // a second run into this --out refuses
  if (!o.out.empty()) {
    io::check_output_dir(o.out + "/frames");
    out_lock.emplace(o.out);
    // Under the lock: no other run is writing these. Only this run's frames may remain.
    if (const std::size_t stale = io::remove_stale_frames(o.out + "/frames"))
      std::cerr << "tecido: note: removed " << stale << " frame files of an earlier run from " << o.out << "/frames\n";
  }
  Simulation sim(scene);
  const auto self_collision = install_self_collision(sim);
  std::string plot_note;
  std::unique_ptr<io::FrameWriter> frames;
  if (o.out.empty()) {
    sim.run(scene.steps);
  } else {
    frames = std::make_unique<io::FrameWriter>(o.out + "/frames", true, o.vtk);
    plot_note = run_with_frames(sim, scene, o, every, *frames);
  }
  io::Json result = io::run_result_json(sim);
  if (self_collision) result["self_collision"] = io::self_collision_json(*self_collision);
  if (!o.out.empty()) {
    // The file outlives the command: it names what made it. stdout is the command's own answer.
    io::Json file = result;
    file["tecido"] = io::provenance_json();
    io::write_file_atomic(o.out + "/result.json", file.dump(2) + "\n");
  }
  if (o.json) {
    if (frames && !plot_note.empty()) std::cerr << "tecido: note: " << plot_note << "\n";
    std::cout << result.dump() << "\n";
  } else {
    print_summary(sim, scene, result, self_collision.get(), frames.get(), o, plot_note);
  }
  print_step_hint(sim, scene);
  return 0;
}

Command add_run(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* sub = app.add_subcommand("run", "Simulate a scene with the core engine");
  sub->add_option("scene", o->scene, "Scene file (JSON)")->required()->check(non_empty());
  sub->add_option("--integrator", o->integrator, "euler | symplectic | midpoint | rk4 (overrides the scene)")
      ->check(one_of({"euler", "symplectic", "midpoint", "rk4"}));
  o->dt_opt = sub->add_option("--dt", o->dt, "Step [s] (overrides the scene)")->check(number_in(0.0, true, io::kMaxDt));
  o->steps_opt = sub->add_option("--steps", o->steps, "Number of steps (overrides the scene)")
                     ->check(integer_in(0, io::kMaxSteps));
  sub->add_flag("--json", o->json, "Print the result as one JSON object");
  CLI::Option* out = sub->add_option("--out", o->out,
                                     "Directory for result.json, frames/ (OBJ per frame; an earlier run's frames there are "
                                     "removed), cloth.svg and index.html (the frames in 3-D in a browser)")
                         ->check(non_empty());
  o->every_opt = sub->add_option("--frame-every", o->frame_every,
                                 "With --out: write every K-th step's frame (default: about 100 frames)")
                     ->check(integer_in(1, io::kMaxSteps))
                     ->needs(out);
  sub->add_flag("--vtk", o->vtk, "With --out: write legacy VTK frames as well as OBJ")->needs(out);
  sub->add_option("--threads", o->threads,
                  "Threads of the self-collision detection (0 = all cores; default 1); results do not depend on it")
      ->capture_default_str()
      ->check(integer_in(0, io::kMaxThreads));
  sub->add_option("--max-work", o->max_work,
                  "Largest work of the run, steps x elements per step (particles, springs, particle-plane tests, "
                  "self-collision triangles)")
      ->capture_default_str()
      ->check(number_in(1.0, false, io::kMaxWorkCeiling));
  return [o]() { return run(*o); };
}

}  // namespace

TECIDO_REGISTER_COMMAND(run, add_run);

}  // namespace tecido::cli
