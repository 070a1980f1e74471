// An engine of the caller's on a query set, every answer against the exact referee
// (include/tecido/harness.h: check_tri_tri, check_ccd, QueryReport::json).
#include "comparisons/engines/outside/engine_error.h"
#include "comparisons/harness/registered_engines.h"
#include "core/api/public_types.h"
#include "reference/exact_ccd.h"
#include "reference/exact_referee.h"

#include <nlohmann/json.hpp>
#include <tecido/harness.h>

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>

namespace tecido::harness {

namespace {

constexpr std::size_t kKeptDisagreements = 100;

/// Counts one answer against the referee's into `report` (and its family's tally).
class Tally {
 public:
  explicit Tally(QueryReport& report) : report_(report) {}

  void add(const std::string& family, const std::string& id, std::optional<bool> answer, bool truth, double toi,
           double truth_toi) {
    ++report_.queries;
    FamilyTally& f = family_tally(family);
    ++f.queries;
    if (answer && *answer == truth) return;
    ++f.disagreements;
    ++report_.disagreements;
    if (!answer) ++report_.undecided;
    else if (truth) ++report_.misses;
    else ++report_.false_hits;
    if (report_.first_disagreements.size() < kKeptDisagreements)
      report_.first_disagreements.push_back(Disagreement{id, answer ? int(*answer) : -1, truth, toi, truth_toi});
  }

 private:
  FamilyTally& family_tally(const std::string& family) {
    auto it = index_.find(family);
    if (it == index_.end()) {
      it = index_.emplace(family, report_.families.size()).first;
      report_.families.push_back(FamilyTally{family, 0, 0});
    }
    return report_.families[it->second];
  }
  QueryReport& report_;
  std::map<std::string, std::size_t> index_;
};

/// The one engine of `engine`'s table, behind the plug-in adapter.
outside::OutsideEnginePtr adapted(const RegisteredEngines& registered) { return registered.engines().front(); }

/// Converts a failing door (an engine throwing through the adapter) into the API's exception.
template <class Fn>
auto calling(Fn&& fn) {
  try {
    return fn();
  } catch (const outside::EngineError& e) {
    throw std::invalid_argument(e.what());
  }
}

}  // namespace

QueryReport check_tri_tri(const tecido_engine& engine, const std::vector<TriTriCase>& cases) {
  const RegisteredEngines registered({engine});
  const auto e = adapted(registered);
  if (!e->capabilities().tri_tri)
    throw std::invalid_argument("harness: engine \"" + e->name() + "\" has no tri_tri function");
  std::vector<outside::TriTriQuery> queries;
  queries.reserve(cases.size());
  for (const TriTriCase& c : cases) queries.push_back(outside::TriTriQuery{c.a, c.b});
  const auto answers = calling([&] { return e->tri_tri(queries); });
  QueryReport report;
  report.engine = e->name();
  Tally tally(report);
  for (std::size_t k = 0; k < cases.size(); ++k)
    tally.add(cases[k].family, cases[k].id, answers[k], reference::exact_tri_tri(cases[k].a, cases[k].b), 0.0, 0.0);
  return report;
}

QueryReport check_ccd(const tecido_engine& engine, const std::vector<CcdCase>& cases) {
  const RegisteredEngines registered({engine});
  const auto e = adapted(registered);
  const outside::Capabilities can = e->capabilities();
  if (!can.ccd_vertex_face && !can.ccd_edge_edge)
    throw std::invalid_argument("harness: engine \"" + e->name() + "\" has no ccd function");
  std::vector<const CcdCase*> asked;
  std::vector<CcdQuery> queries;
  for (const CcdCase& c : cases) {
    const bool vf = c.motion.kind == MotionKind::VertexFace;
    if (vf ? !can.ccd_vertex_face : !can.ccd_edge_edge) continue;
    asked.push_back(&c);
    queries.push_back(api::ccd_query(c.motion));
  }
  const auto answers = calling([&] { return e->ccd(queries); });
  QueryReport report;
  report.engine = e->name();
  Tally tally(report);
  for (std::size_t k = 0; k < asked.size(); ++k) {
    const reference::ExactCcd truth = reference::exact_ccd(queries[k]);
    const std::optional<CcdAnswer>& a = answers[k];
    if (a && a->hit && truth.hit) report.max_late_toi = std::max(report.max_late_toi, a->toi - truth.toi_hi);
    tally.add(asked[k]->family, asked[k]->id, a ? std::optional<bool>(a->hit) : std::nullopt, truth.hit,
              a && a->hit ? a->toi : 0.0, truth.toi);
  }
  return report;
}

std::string QueryReport::json() const {
  nlohmann::json fams = nlohmann::json::array(), first = nlohmann::json::array();
  for (const FamilyTally& f : families)
    fams.push_back({{"family", f.family}, {"queries", f.queries}, {"disagreements", f.disagreements}});
  for (const Disagreement& d : first_disagreements)
    first.push_back({{"id", d.id}, {"answer", d.answer}, {"truth", d.truth}, {"toi", d.toi}, {"truth_toi", d.truth_toi}});
  const nlohmann::json j = {{"engine", engine},         {"queries", queries},       {"disagreements", disagreements},
                            {"misses", misses},         {"false_hits", false_hits}, {"undecided", undecided},
                            {"max_late_toi", max_late_toi}, {"families", fams},     {"first_disagreements", first}};
  return j.dump(2);
}

}  // namespace tecido::harness
