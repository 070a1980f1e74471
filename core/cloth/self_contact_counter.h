#pragma once
/// Counting frames with self-contact, the measure of the seed's experiment (section 3.1.3,
/// tables 1-3: "the share of iterations in which contacts were detected"), with a chosen
/// triangle-triangle test. What counts as a contact depends on the test:
///   core           tri_tri_intersect: exact, closed triangles (the harness's detector);
///   core-mt        tri_tri_moller_trumbore: the seed's detector as it describes it
///                  (Möller-Trumbore on the edges of each triangle against the other, both ways
///                  must hit; misses one-sided piercings, see its header);
///   core-rotation  tri_tri_rotation: the seed's first test (fig. 18).
/// The counter only looks: it never changes the simulation, so several counters on one run
/// compare the detectors on identical frames. The names are the tri-tri engine names of the CLI.
#include "core/cloth/self_collision.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido {

enum class ContactTest { Core, CoreMt, CoreRotation };

/// "core", "core-mt", "core-rotation".
const char* contact_test_name(ContactTest t);
/// The names above; nothing for an unknown name.
std::optional<ContactTest> parse_contact_test(const std::string& name);
/// The triangle-triangle function of the test.
TriTriTest contact_test_function(ContactTest t);

struct SelfContactCount {
  long long frames = 0;          ///< frames counted
  long long contact_frames = 0;  ///< ... with at least one intersecting pair
  long long pairs = 0;           ///< intersecting pairs, summed over frames
  long long max_pairs = 0;       ///< most pairs in one frame
};

class SelfContactCounter {
 public:
  /// For the mesh `triangles`, its box tree built on positions x_build.
  SelfContactCounter(const std::vector<std::array<int, 3>>& triangles, const std::vector<Vec3>& x_build,
                     ContactTest test);

  /// Detects the intersecting pairs at x with the test and counts the frame; returns the pairs
  /// (valid until the next call).
  const std::vector<TrianglePair>& count(const std::vector<Vec3>& x);
  /// Counts a frame whose `pairs` intersecting pairs were found elsewhere with the same test.
  void count_pairs(std::size_t pairs);

  ContactTest test() const { return test_; }
  const SelfContactCount& counts() const { return counts_; }

 private:
  ContactTest test_;
  SelfCollisionDetector detector_;
  SelfContactCount counts_;
};

}  // namespace tecido
