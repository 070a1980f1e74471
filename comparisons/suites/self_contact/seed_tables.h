#pragma once
/// The seed's tables 1-3 (section 3.1.3; data/seed_tables/self_contact_share.json): its share of
/// frames with self-contact for each of the 72 cells, one run each, counted with its
/// Möller-Trumbore detector.
#include "comparisons/suites/self_contact/grid.h"

#include <array>
#include <string>

namespace tecido::suites::self_contact {

struct SeedTables {
  std::string file;
  std::array<double, CellGrid::kCells> share{};  ///< by cell index; NaN where the tables have no value
};

/// Reads the tables document {"tables":[{"wind","rows":[{"steps_per_second","elasticity","none",
/// "mode1","mode2","mode3"}]}]}; throws io::InputError naming the file and pointer of a bad value.
SeedTables read_seed_tables(const std::string& path);

}  // namespace tecido::suites::self_contact
