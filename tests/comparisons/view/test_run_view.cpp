#include "comparisons/io/source_dir.h"
#include "comparisons/view/run_view.h"

#include "comparisons/io/scene_json.h"
#include "core/dynamics/springs_through_obstacle.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cstring>

namespace tecido::view {
namespace {

std::vector<std::uint32_t> words(const std::string& b64) {
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> bytes;
  std::uint32_t acc = 0;
  int bits = 0;
  for (char c : b64) {
    if (c == '=') break;
    acc = (acc << 6) | static_cast<std::uint32_t>(alphabet.find(c));
    bits += 6;
    if (bits >= 8) bits -= 8, bytes.push_back(static_cast<unsigned char>(acc >> bits));
  }
  std::vector<std::uint32_t> out(bytes.size() / 4);
  for (std::size_t k = 0; k < out.size(); ++k)
    for (int b = 0; b < 4; ++b) out[k] |= std::uint32_t{bytes[4 * k + b]} << (8 * b);
  return out;
}

std::vector<float> floats(const std::string& b64) {
  const auto w = words(b64);
  std::vector<float> out(w.size());
  std::memcpy(out.data(), w.data(), w.size() * 4);
  return out;
}

// The block scene (seed figs. 10-13) drapes over the box: its page's per-frame springs through the
// obstacle and self-contact pairs are core's detectors' answers on the recorded positions, checked
// against the brute-force self-collision reference and springs_through_obstacle.
TEST(RunView, FramesHoldThePositionsAndTheDetectorsAnswers) {
  const Scene scene = io::load_scene(std::string(TECIDO_SOURCE_DIR) + "/data/scenes/seed_fig10_12_block_121.json");
  Simulation sim(scene);
  RunView view(scene);
  std::vector<std::vector<Vec3>> xs;
  std::vector<double> ts;
  auto record = [&](const Simulation& s) {
    if (s.steps_done() % 100 != 0) return;
    ASSERT_TRUE(view.add(s.steps_done(), s.time(), s.particles().x));
    xs.push_back(s.particles().x);
    ts.push_back(s.time());
  };
  record(sim);
  sim.run(600, record);
  const io::Json d = view.data("block");
  ASSERT_EQ(d["frames"].get<std::size_t>(), xs.size());
  const std::size_t n = scene.particles.size();
  const auto pos = floats(d["positions"]);
  ASSERT_EQ(pos.size(), xs.size() * n * 3);
  const auto c_off = words(d["contacts"]["offsets"]), c_pairs = words(d["contacts"]["pairs"]);
  const auto s_off = words(d["through"]["offsets"]), s_list = words(d["through"]["springs"]);
  ASSERT_EQ(c_off.size(), xs.size() + 1);
  int through_any = 0;
  for (std::size_t f = 0; f < xs.size(); ++f) {
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(pos[(f * n + i) * 3 + c], static_cast<float>(xs[f][i][c]));
    const auto brute = self_collision_pairs_brute(xs[f], scene.triangles);
    ASSERT_EQ(c_off[f + 1] - c_off[f], brute.size());
    for (std::size_t k = 0; k < brute.size(); ++k) {
      EXPECT_EQ(c_pairs[2 * (c_off[f] + k)], static_cast<std::uint32_t>(brute[k][0]));
      EXPECT_EQ(c_pairs[2 * (c_off[f] + k) + 1], static_cast<std::uint32_t>(brute[k][1]));
    }
    const int expected = springs_through_obstacle(scene.obstacles[0], ts[f], scene.forces.springs, xs[f]);
    EXPECT_EQ(static_cast<int>(s_off[f + 1] - s_off[f]), expected) << "frame " << f;
    for (std::uint32_t k = s_off[f]; k < s_off[f + 1]; ++k) {
      const Spring& s = scene.forces.springs[s_list[k]];
      EXPECT_TRUE(segment_through_obstacle(scene.obstacles[0], ts[f], xs[f][s.i], xs[f][s.j]));
    }
    through_any += expected;
  }
  EXPECT_GT(through_any, 0) << "the scene's documented artefact: springs cut through the block's edge";
  // A still box: one frame of its 8 corners.
  ASSERT_EQ(d["obstacles"].size(), 1u);
  EXPECT_EQ(floats(d["obstacles"][0]["positions"]).size(), d["obstacles"][0]["vertices"].get<std::size_t>() * 3);
}

TEST(RunView, NonFiniteFramesAreSkipped) {
  const Scene scene = io::load_scene(std::string(TECIDO_SOURCE_DIR) + "/data/scenes/seed_fig10_12_block_121.json");
  RunView view(scene);
  std::vector<Vec3> x = scene.particles.x;
  x[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(view.add(0, 0.0, x));
  EXPECT_TRUE(view.add(1, 0.002, scene.particles.x));
  EXPECT_EQ(view.frames(), 1);
}

TEST(RunView, FrameStrideBoundsThePage) {
  EXPECT_EQ(view_frame_stride(1000, 10, 121), 1);
  // 1e6 frames of 4096 particles: 1.2e10 floats, so every 246th frame.
  EXPECT_EQ(view_frame_stride(1000000, 1, 4096), static_cast<long long>(std::ceil(1000002.0 * 4096 * 3 / kMaxViewFloats)));
}

}  // namespace
}  // namespace tecido::view
