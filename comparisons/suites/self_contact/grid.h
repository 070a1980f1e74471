#pragma once
/// The seed's 72 runs (section 3.1.3, tables 1-3) as a grid of cells: wind {0.09, 0.1, 0.11} N x
/// step {0.02, 0.01, 0.005} s x cloth elasticity {0.9, 0.5} x response {none, edge mode 1, 2, 3}.
/// A cell is named by its four level indices (CellKey) or by one index 0..71:
///   index = ((wind * 3 + step) * 2 + elasticity) * 4 + mode,
/// the seed's table order (table = wind; rows = steps per second, then elasticity; columns = mode).
#include <array>
#include <string>

namespace tecido::suites::self_contact {

/// Level indices of a cell: wind 0..2, step 0..2, elasticity 0..1, mode 0..3 (0 = no response).
struct CellKey {
  int wind = 0, step = 0, elasticity = 0, mode = 0;
  bool operator==(const CellKey& o) const {
    return wind == o.wind && step == o.step && elasticity == o.elasticity && mode == o.mode;
  }
};

/// A cell's values.
struct Cell {
  int index = 0;
  CellKey key;
  double wind = 0.0;        ///< [N]
  double dt = 0.0;          ///< [s]
  double elasticity = 0.0;  ///< the seed's "elasticidade do tecido"
  int mode = 0;             ///< 0 = no response, 1..3 = the seed's edge modes
  int steps_per_second() const;
};

struct CellGrid {
  static constexpr int kWinds = 3, kSteps = 3, kElasticities = 2, kModes = 4;
  static constexpr int kCells = kWinds * kSteps * kElasticities * kModes;  // 72
  static constexpr std::array<double, kWinds> winds{0.09, 0.1, 0.11};
  static constexpr std::array<double, kSteps> steps{0.02, 0.01, 0.005};
  static constexpr std::array<double, kElasticities> elasticities{0.9, 0.5};

  /// The index of a key (levels in range), and back.
  static int index(const CellKey& k);
  static CellKey key(int index);
  /// The cell of an index 0..71.
  static Cell cell(int index);
  /// The same (wind, step, elasticity) with another mode.
  static int with_mode(int index, int mode);
};

/// "none", "mode 1", ... for reports; the scene's response names "none", "edge1", "edge2", "edge3".
std::string mode_label(int mode);
const char* mode_response_name(int mode);

}  // namespace tecido::suites::self_contact
