#include "comparisons/suites/plane/disagreements.h"

#include "comparisons/io/atomic_file.h"

namespace tecido::suites::plane {

std::vector<io::PlaneCase> disagreement_cases(std::uint64_t seed, const std::vector<Category>& categories,
                                              const AgreementTable& table, std::size_t cap) {
  std::vector<io::PlaneCase> out;
  for (const auto& per_engine : table.disagree) {
    for (const Disagreement& d : per_engine) {
      if (out.size() >= cap) return out;
      io::PlaneCase c = category_case(seed, d.category, categories.at(d.category), d.k);
      c.id = table.engines.at(d.engine) + ":" + c.id;
      out.push_back(std::move(c));
    }
  }
  return out;
}

long disagreements_found(const AgreementTable& table) {
  long n = 0;
  for (const auto& per_category : table.tally)
    for (const Tally& t : per_category) n += t.false_hits + t.misses;
  return n;
}

void write_disagreements(const std::string& path, const std::vector<io::PlaneCase>& cases) {
  io::write_file_atomic(path, io::plane_cases_to_json(cases).dump(1) + "\n");
}

}  // namespace tecido::suites::plane
