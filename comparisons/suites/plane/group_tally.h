#pragma once
/// The `plane` suite checks agreement per group of categories (check_plan.h): a group's tally is
/// the sum of its categories' tallies (comparisons/suites/agreement/table.h).
#include "comparisons/suites/agreement/table.h"
#include "comparisons/suites/plane/categories.h"
#include "comparisons/suites/plane/check_plan.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tecido::suites::plane {

using agreement::AgreementTable;
using agreement::Tally;

/// A group's tally for engine e, summed over the group's categories present in `categories`, or
/// the reason it has no value: the first error among them ("edge: case 3 threw: ...").
struct GroupTally {
  Tally tally;
  std::string error;
};
GroupTally group_tally(const AgreementTable& table, const std::vector<Category>& categories, const CategoryGroup& group,
                       std::size_t e);

}  // namespace tecido::suites::plane
