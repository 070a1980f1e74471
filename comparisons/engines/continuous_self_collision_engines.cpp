#include "comparisons/engines/continuous_self_collision_engines.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "reference/exact_ccd.h"
#include "reference/exact_self_contacts.h"

#include <stdexcept>

namespace tecido {

namespace {

CcdAnswer exact_continuous_test(const CcdQuery& q) { return reference::to_ccd_answer(reference::exact_ccd(q)); }

}  // namespace

const std::vector<std::string>& continuous_self_collision_engines() {
  static const std::vector<std::string> names = {"core", "core-brute", "exact"};
  return names;
}

void check_continuous_self_collision_size(const std::string& engine, std::size_t triangles, const std::string& mesh,
                                          const std::string& option) {
  const std::size_t limit = engine == "core-brute" ? io::kMaxBruteForceTriangles
                            : engine == "exact"    ? kMaxExactContinuousTriangles
                                                   : 0;
  if (limit && triangles > limit)
    throw io::UsageError(option + ": " + engine + " tests every pair and takes at most " + std::to_string(limit) +
                         " triangles, but " + mesh + " has " + std::to_string(triangles) + " (use core)");
}

ContinuousContacts continuous_self_collision_contacts(const std::string& name, const std::vector<Vec3>& x0,
                                                      const std::vector<Vec3>& x1,
                                                      const std::vector<std::array<int, 3>>& triangles,
                                                      int threads) {
  if (name == "core-brute") return continuous_self_collision_brute(x0, x1, triangles);
  if (name == "exact") return continuous_self_collision_brute(x0, x1, triangles, &exact_continuous_test);
  if (name != "core") throw std::invalid_argument("no continuous self-collision engine \"" + name + "\"");
  return reference::exact_self_contacts(x0, x1, triangles, threads);
}

}  // namespace tecido
