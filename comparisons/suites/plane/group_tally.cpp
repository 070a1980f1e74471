#include "comparisons/suites/plane/group_tally.h"

namespace tecido::suites::plane {

GroupTally group_tally(const AgreementTable& table, const std::vector<Category>& categories, const CategoryGroup& group,
                       std::size_t e) {
  GroupTally g;
  for (const std::string& name : group.categories) {
    for (std::size_t c = 0; c < categories.size(); ++c) {
      if (categories[c].name != name) continue;
      if (!table.error[c].empty() && g.error.empty()) g.error = name + ": " + table.error[c];
      g.tally.add(table.tally[c][e]);
    }
  }
  return g;
}

}  // namespace tecido::suites::plane
