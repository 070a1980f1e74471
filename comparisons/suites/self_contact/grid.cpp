#include "comparisons/suites/self_contact/grid.h"

#include <cmath>

namespace tecido::suites::self_contact {

int Cell::steps_per_second() const { return static_cast<int>(std::lround(1.0 / dt)); }

int CellGrid::index(const CellKey& k) {
  return ((k.wind * kSteps + k.step) * kElasticities + k.elasticity) * kModes + k.mode;
}

CellKey CellGrid::key(int index) {
  CellKey k;
  k.mode = index % kModes;
  k.elasticity = (index / kModes) % kElasticities;
  k.step = (index / (kModes * kElasticities)) % kSteps;
  k.wind = index / (kModes * kElasticities * kSteps);
  return k;
}

Cell CellGrid::cell(int index) {
  Cell c;
  c.index = index;
  c.key = key(index);
  c.wind = winds[c.key.wind];
  c.dt = steps[c.key.step];
  c.elasticity = elasticities[c.key.elasticity];
  c.mode = c.key.mode;
  return c;
}

int CellGrid::with_mode(int index, int mode) {
  CellKey k = key(index);
  k.mode = mode;
  return CellGrid::index(k);
}

std::string mode_label(int mode) { return mode == 0 ? "none" : "mode " + std::to_string(mode); }

const char* mode_response_name(int mode) {
  static const char* const names[4] = {"none", "edge1", "edge2", "edge3"};
  return names[mode];
}

}  // namespace tecido::suites::self_contact
