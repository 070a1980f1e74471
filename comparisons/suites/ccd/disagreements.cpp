#include "comparisons/suites/ccd/disagreements.h"

namespace tecido::suites::ccd {

void add_disagreements(const std::string& family, const FamilyResult& r, const std::vector<KnownQuery>& queries,
                       const std::vector<std::string>& engines, std::size_t cap, std::vector<io::CcdQueryEntry>& out) {
  for (const agreement::Disagreement& d : r.disagree) {
    if (out.size() >= cap) return;
    io::CcdQueryEntry e;
    e.id = engines.at(d.engine) + ":" + family + "/" + std::to_string(d.k);
    e.query = queries.at(static_cast<std::size_t>(d.k)).q;
    e.truth = d.truth.hit;
    out.push_back(std::move(e));
  }
}

}  // namespace tecido::suites::ccd
