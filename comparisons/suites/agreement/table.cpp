#include "comparisons/suites/agreement/table.h"

#include <cmath>

namespace tecido::suites::agreement {

AgreementTable empty_table(std::size_t families, const std::vector<std::string>& engines) {
  AgreementTable t;
  t.engines = engines;
  t.error.assign(families, "");
  t.hits.assign(families, 0);
  t.tally.assign(families, std::vector<Tally>(engines.size()));
  t.random_seconds.assign(engines.size(), 0.0);
  t.random_timed.assign(engines.size(), 0);
  t.disagree.assign(engines.size(), {});
  return t;
}

double ns_per_case(const AgreementTable& table, std::size_t e) {
  const long n = table.random_timed.at(e);
  return n > 0 ? 1e9 * table.random_seconds[e] / static_cast<double>(n) : std::nan("");
}

long disagreements_found(const AgreementTable& table) {
  long n = 0;
  for (const auto& per_family : table.tally)
    for (const Tally& t : per_family) n += t.disagreements();
  return n;
}

std::vector<Disagreement> kept_disagreements(const AgreementTable& table, std::size_t cap) {
  std::vector<Disagreement> out;
  for (const auto& per_engine : table.disagree)
    for (const Disagreement& d : per_engine) {
      if (out.size() >= cap) return out;
      out.push_back(d);
    }
  return out;
}

}  // namespace tecido::suites::agreement
