#include "comparisons/suites/ccd/disagreements.h"

#include "comparisons/suites/agreement/replay.h"

namespace tecido::suites::ccd {

void add_disagreements(const std::string& family, const FamilyResult& r, const std::vector<KnownQuery>& queries,
                       const std::vector<std::string>& engines, std::size_t cap, std::vector<KeptDisagreement>& out) {
  for (const agreement::Disagreement& d : r.disagree) {
    if (out.size() >= cap) return;
    KeptDisagreement k;
    k.entry.id = engines.at(d.engine) + ":" + family + "/" + std::to_string(d.k);
    k.entry.query = queries.at(static_cast<std::size_t>(d.k)).q;
    k.entry.truth = d.truth.hit;
    k.d = d;
    out.push_back(std::move(k));
  }
}

io::Json disagreements_json(const std::vector<KeptDisagreement>& kept, const std::vector<std::string>& engines) {
  std::vector<io::CcdQueryEntry> entries;
  std::vector<agreement::Disagreement> ds;
  for (const KeptDisagreement& k : kept) entries.push_back(k.entry), ds.push_back(k.d);
  io::Json doc = io::ccd_queries_to_json(entries);
  agreement::label_entries(doc, "queries", engines, ds, "toi");
  return doc;
}

}  // namespace tecido::suites::ccd
