#include "core/cloth/self_contact_counter.h"

#include "core/geometry/tri_tri_intersect.h"
#include "core/geometry/tri_tri_moller_trumbore.h"
#include "core/geometry/tri_tri_rotation.h"

#include <algorithm>

namespace tecido {

const char* contact_test_name(ContactTest t) {
  switch (t) {
    case ContactTest::Core: return "core";
    case ContactTest::CoreMt: return "core-mt";
    case ContactTest::CoreRotation: return "core-rotation";
  }
  return "core";
}

std::optional<ContactTest> parse_contact_test(const std::string& name) {
  for (auto t : {ContactTest::Core, ContactTest::CoreMt, ContactTest::CoreRotation})
    if (name == contact_test_name(t)) return t;
  return std::nullopt;
}

TriTriTest contact_test_function(ContactTest t) {
  switch (t) {
    case ContactTest::Core: return &tri_tri_intersect;
    case ContactTest::CoreMt: return &tri_tri_moller_trumbore;
    case ContactTest::CoreRotation: return &tri_tri_rotation;
  }
  return &tri_tri_intersect;
}

SelfContactCounter::SelfContactCounter(const std::vector<std::array<int, 3>>& triangles,
                                       const std::vector<Vec3>& x_build, ContactTest test)
    : test_(test), detector_(triangles, x_build, contact_test_function(test)) {}

const std::vector<TrianglePair>& SelfContactCounter::count(const std::vector<Vec3>& x) {
  const auto& pairs = detector_.detect(x);
  count_pairs(pairs.size());
  return pairs;
}

void SelfContactCounter::count_pairs(std::size_t pairs) {
  ++counts_.frames;
  if (pairs == 0) return;
  ++counts_.contact_frames;
  counts_.pairs += static_cast<long long>(pairs);
  counts_.max_pairs = std::max(counts_.max_pairs, static_cast<long long>(pairs));
}

}  // namespace tecido
