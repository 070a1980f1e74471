#pragma once
// The outside engines the tests load (built by tests/CMakeLists.txt and examples/), and triangle
// pairs whose answers are worked out by hand, with what the seed's Moller-Trumbore rule (an edge
// of A hits B AND an edge of B hits A, |det| >= 1e-6) and the Python example's rule (an edge of
// either hits the other, det != 0) answer on each.
#include "comparisons/io/source_dir.h"
#include "core/geometry/types.h"

#include <string>
#include <vector>

namespace tecido::testing {

inline const std::string kExamplePlugin = TECIDO_EXAMPLE_PLUGIN;      // mt-plugin, euler-plugin (claims 1), sampled-ccd
inline const std::string kLiarPlugin = TECIDO_LIAR_PLUGIN;            // mt-plugin, euler-liar (explicit Euler, claims 2), sampled-ccd (vertex-face only)
inline const std::string kNoEntryPlugin = TECIDO_NO_ENTRY_PLUGIN;     // exports no tecido_plugin_entry
inline const std::string kFutureAbiPlugin = TECIDO_FUTURE_ABI_PLUGIN; // abi_version 99
// Commands as a user types them (the source path has no blanks; tests quote the whole command).
inline const std::string kPythonEngine = std::string("python3 ") + TECIDO_SOURCE_DIR + "/examples/python/tecido_engine.py";
inline std::string misbehaving_engine(const std::string& mode) {
  return std::string("python3 ") + TECIDO_SOURCE_DIR + "/tests/comparisons/engines/outside/fixtures/misbehaving_engine.py " + mode;
}

struct HandPair {
  const char* id;
  Triangle a, b;
  bool truth;  ///< closed triangles share a point
  bool mt;     ///< the seed's MT rule
  bool edges;  ///< the Python example's rule
};

inline std::vector<HandPair> hand_pairs() {
  return {
      // a in z = 0 (x, y >= -1, x + y <= 2); b in y = 0 over (x, z) = (0,-1), (0,1), (5,0). b's edge x = 0
      // crosses a at the origin; a's edge x + y = 2 crosses y = 0 at (2, 0, 0), inside b. Both pierce.
      {"pierce-both", {Vec3(-1, -1, 0), Vec3(3, -1, 0), Vec3(-1, 3, 0)}, {Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(5, 0, 0)},
       true, true, true},
      // A unit triangle stabbing a triangle 20 m wide: b's edge (0,0,-0.5)-(1,0,0.5) crosses a at (0.5, 0, 0);
      // a's edges are 10 m away from b. Only b pierces: the AND rule misses it.
      {"stab", {Vec3(-10, -10, 0), Vec3(10, -10, 0), Vec3(0, 10, 0)}, {Vec3(0, 0, -0.5), Vec3(1, 0, 0.5), Vec3(0, 1, 0.5)},
       true, false, true},
      // Coplanar overlap in z = 0: (1, 0.25) is inside a. Every det is exactly 0: both rules miss it.
      {"coplanar", {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)}, {Vec3(1, 0.25, 0), Vec3(3, 0.25, 0), Vec3(1, 2.25, 0)},
       true, false, false},
      // b touches a's face at one point, its vertex (1, 1, 0); the rest of b is above. b's edges from that vertex
      // hit a at t = 0 exactly; no edge of a reaches b: the AND rule misses the touch.
      {"touching", {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 4, 0)}, {Vec3(1, 1, 0), Vec3(1, 1, 2), Vec3(2, 1, 2)},
       true, false, true},
      // Parallel planes 2 m apart.
      {"apart", {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {Vec3(0, 0, 2), Vec3(1, 0, 2), Vec3(0, 1, 2)}, false,
       false, false},
  };
}

}  // namespace tecido::testing
