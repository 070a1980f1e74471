#pragma once
/// The `plane` suite's report on the drop group: the method (from the settings), the table of every
/// height, conclusions derived from it, and report.json data.
#include "comparisons/suites/plane/drop.h"

#include <string>
#include <vector>

namespace tecido::suites::plane {

/// Every height's row, or the error of its case ("" when it ran).
struct DropTable {
  std::vector<DropRow> rows;
  std::vector<std::string> error;
};

std::string drop_method(const DropSettings& s, bool bullet);
std::string drop_table(const DropTable& t, bool bullet);
/// Core's contact time and apex error; Bullet's rigid sphere's contact in steps and apex error; the
/// node's contact and whether it rebounds above its margin, with what the twin lists as not modelled.
std::string drop_conclusions(const DropSettings& s, const DropTable& t);
/// [{"z0", "t_exact", ...} or {"z0", "error"}] in height order.
io::Json drop_data(const DropTable& t);

}  // namespace tecido::suites::plane
