#include "comparisons/suites/tritri/disagreements.h"

#include "comparisons/io/atomic_file.h"

namespace tecido::suites::tritri {

std::vector<io::TriPair> disagreement_pairs(std::uint64_t seed, const std::vector<Family>& families,
                                            const AgreementTable& table, std::size_t cap) {
  std::vector<io::TriPair> out;
  for (const auto& per_engine : table.disagree) {
    for (const Disagreement& d : per_engine) {
      if (out.size() >= cap) return out;
      io::TriPair p = family_pair(seed, d.family, families.at(d.family), d.k);
      p.id = table.engines.at(d.engine) + ":" + p.id;
      out.push_back(std::move(p));
    }
  }
  return out;
}

long disagreements_found(const AgreementTable& table) {
  long n = 0;
  for (const auto& per_family : table.tally)
    for (const Tally& t : per_family) n += t.pairs - t.agree - t.no_answer;
  return n;
}

void write_disagreements(const std::string& path, const std::vector<io::TriPair>& pairs) {
  io::write_file_atomic(path, io::tri_pairs_to_json(pairs).dump() + "\n");
}

}  // namespace tecido::suites::tritri
