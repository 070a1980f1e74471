// comparisons/io/scene_json.cpp, the wind's "random" key (read_random_heading): what it sets and
// the one-line errors of bad values (file, JSON pointer, problem).
#include "comparisons/io/input_error.h"
#include "comparisons/io/scene_json.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

io::Json scene(const io::Json& wind) {
  return {{"dt", 0.01}, {"steps", 250}, {"seed", 9}, {"wind", wind},
          {"particles", io::Json::array({{{"position", {0, 0, 0}}, {"mass", 1.0}}})}};
}

TEST(SceneRandomWind, SetsTheHeadingAndPreparesItsKnots) {
  const io::Json swirl = {{"rate", 0.5}, {"axis", {0, 1, 0}}};
  const Scene s = io::scene_from_json(
      scene({{"force", {0.1, 0, 0}}, {"swirl", swirl}, {"random", {{"heading_diffusion", 0.2}, {"knot_interval", 0.05}}}}), "s.json");
  ASSERT_TRUE(s.forces.wind && s.forces.wind->random);
  const RandomHeading& h = *s.forces.wind->random;
  EXPECT_EQ(h.seed, 9u);  // the scene's seed by default
  EXPECT_EQ(h.diffusion, 0.2);
  EXPECT_EQ(h.knot_interval, 0.05);
  EXPECT_GE(h.knots.size(), 51u);  // 2.5 s at 0.05 s
  const Scene t = io::scene_from_json(
      scene({{"force", {0.1, 0, 0}}, {"swirl", swirl}, {"random", {{"seed", 4}, {"heading_diffusion", 0}}}}), "t.json");
  EXPECT_EQ(t.forces.wind->random->seed, 4u);
  EXPECT_EQ(t.forces.wind->random->knot_interval, 0.1);
}

TEST(SceneRandomWind, BadValuesNameTheirPointer) {
  const io::Json swirl = {{"rate", 0.5}};
  const struct {
    io::Json wind;
    const char* pointer;
  } cases[] = {
      {{{"force", {0.1, 0, 0}}, {"random", {{"heading_diffusion", 0.1}}}}, "/wind/random"},  // no swirl
      {{{"force", {0.1, 0, 0}}, {"swirl", swirl}, {"random", {{"heading_diffusion", -1}}}}, "/wind/random/heading_diffusion"},
      {{{"force", {0.1, 0, 0}}, {"swirl", swirl}, {"random", io::Json::object()}}, "/wind/random/heading_diffusion"},
      {{{"force", {0.1, 0, 0}}, {"swirl", swirl}, {"random", {{"heading_diffusion", 0.1}, {"knot_interval", 0}}}},
       "/wind/random/knot_interval"},
      {{{"force", {0.1, 0, 0}}, {"swirl", swirl}, {"random", {{"heading_diffusion", 0.1}, {"seed", -3}}}}, "/wind/random/seed"},
      {{{"force", {0.1, 0, 0}}, {"swirl", swirl}, {"random", {{"heading_diffusion", 0.1}, {"sed", 3}}}}, "/wind/random/sed"},
      {{{"force", {0.1, 0, 0}}, {"swirl", swirl}, {"random", 3}}, "/wind/random"},
  };
  for (const auto& c : cases) {
    try {
      io::scene_from_json(scene(c.wind), "bad.json");
      ADD_FAILURE() << c.wind.dump() << " was accepted";
    } catch (const io::InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("bad.json"), std::string::npos) << what;
      EXPECT_NE(what.find(c.pointer), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace tecido
