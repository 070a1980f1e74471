#pragma once
/// The contact-time group of the `plane` suite (seed fig. 8): particles dropped on a floor under
/// gravity, the first contact's bisected time from core's contact log against the analytic root
/// (theory.h), for one integrator, step and bisection tolerance per case.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/plane/settings.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::suites::plane {

/// Drop d of every cell: a particle at height z0 with velocity v over the floor z = 0.
struct DropStart {
  double z0 = 0.0;
  Vec3 v = Vec3::Zero();
};
/// Drop d's start, from substream(seed, s.first_stream + d).
DropStart drop_start(const ContactTimeSettings& s, std::uint64_t seed, int d);

/// The scene of one drop: one particle, gravity, the floor, the integrator, step h and bisection
/// tolerance.
Scene drop_scene(const ContactTimeSettings& s, const DropStart& start, IntegratorKind k, double h, double tolerance);

/// One cell: every drop at integrator k, step h, tolerance h 2^-level.
struct ContactCellResult {
  double tolerance = 0.0;
  double max_error = 0.0;       ///< max |t_contact - t_analytic| over the drops that touched [s]
  int contacts = 0;             ///< drops that touched the floor within max_time
  int first_missing = -1;       ///< the first drop that did not (-1: none)
  double bisections = 0.0;      ///< integrator calls spent bisecting, per contact
  double seconds = 0.0;         ///< thread CPU time of the drops' step loops
};
ContactCellResult run_contact_cell(const ContactTimeSettings& s, std::uint64_t seed, IntegratorKind k, double h, int level);

/// Every cell of the table, [integrator][step][level] as in the settings; `error` is the message of
/// a cell whose case threw ("" otherwise).
struct ContactTable {
  std::vector<std::vector<std::vector<ContactCellResult>>> cells;
  std::vector<std::vector<std::vector<std::string>>> error;
};
/// An empty table shaped like `s` (every cell default, no error).
ContactTable empty_contact_table(const ContactTimeSettings& s);

/// Why a cell has no usable value: its case's error, or the first drop that never touched
/// ("" when the cell is complete).
std::string missing_reason(const ContactTimeSettings& s, const ContactCellResult& r, const std::string& error);

io::Json cell_json(const ContactCellResult& r);
ContactCellResult cell_from_json(const io::Json& j);

}  // namespace tecido::suites::plane
