#include "comparisons/suites/ccd/family_case.h"

#include "comparisons/engines/ccd_engines.h"
#include "reference/exact_ccd.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tecido::suites::ccd {

namespace {

using reference::ExactCcd;

bool same(const ExactCcd& a, const ExactCcd& b) {
  return a.hit == b.hit && (!a.hit || (a.toi == b.toi && a.toi_lo == b.toi_lo && a.toi_hi == b.toi_hi &&
                                       a.toi_exact == b.toi_exact));
}

/// Whether the referee reproduces the constructed answer (the constructed toi is a double).
bool matches_construction(const ExactCcd& e, const KnownQuery& kq) {
  if (e.hit != (kq.known == 1)) return false;
  return !e.hit || (e.toi_exact && e.toi == kq.toi);
}

/// The referee's answers, with its consistency counted into r.
std::vector<ExactCcd> referee(const std::vector<KnownQuery>& queries, const Settings& s, FamilyResult& r) {
  std::vector<ExactCcd> truth(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    truth[i] = reference::exact_ccd(queries[i].q);
    r.contacts += truth[i].hit;
    if (queries[i].known >= 0) {
      ++r.known;
      r.known_mismatch += !matches_construction(truth[i], queries[i]);
    }
    if (i < s.unfiltered_per_family) {
      ++r.unfiltered;
      r.unfiltered_mismatch += !same(truth[i], reference::exact_ccd_unfiltered(queries[i].q));
    }
  }
  return truth;
}

/// Both hit: the time-of-impact error's sum, whether toi is certainly after t*, and how late it is.
void toi_figures(const CcdAnswer& a, const ExactCcd& e, EngineTally& t) {
  t.sum_toi_error += std::fabs(a.toi - e.toi);
  // t* is e.toi when exact, otherwise strictly between the adjacent doubles toi_lo and toi_hi.
  t.toi_after += a.toi > (e.toi_exact ? e.toi : e.toi_lo);
  t.max_toi_late = std::max(t.max_toi_late, a.toi - e.toi);
}

/// One engine on the block: timed answers, then the tally against the truth (agreement kit).
EngineTally tally_engine(const SuiteEngine& engine, std::size_t engine_index, const std::vector<KnownQuery>& queries,
                         const std::vector<ExactCcd>& truth, const Settings& s, FamilyResult& r) {
  EngineTally t;
  const std::vector<std::optional<CcdAnswer>> got = answer_block(engine, queries, t.seconds);
  t.engine = engine.name;
  std::vector<agreement::Answer> want(queries.size());
  std::vector<std::optional<agreement::Answer>> answers(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    want[i] = {truth[i].hit, truth[i].toi};
    if (got[i]) answers[i] = agreement::Answer{got[i]->hit, got[i]->toi};
  }
  std::vector<agreement::Disagreement> disagree;
  const std::size_t room = s.max_disagreements - std::min(s.max_disagreements, r.disagree.size());
  t.tally = agreement::count_agreement(want, answers, &disagree, 0, room);
  for (agreement::Disagreement& d : disagree) {
    d.engine = engine_index;
    r.disagree.push_back(d);
  }
  for (std::size_t i = 0; i < queries.size(); ++i)
    if (got[i] && got[i]->hit && truth[i].hit) toi_figures(*got[i], truth[i], t);
  return t;
}

}  // namespace

FamilyResult run_family(const std::string& family, const std::vector<KnownQuery>& queries, const Settings& s,
                        const std::vector<SuiteEngine>& engines) {
  FamilyResult r;
  r.family = family;
  r.queries = static_cast<long>(queries.size());
  const std::vector<ExactCcd> truth = referee(queries, s, r);
  for (std::size_t k = 0; k < engines.size(); ++k)
    r.engines.push_back(tally_engine(engines[k], k, queries, truth, s, r));
  return r;
}

}  // namespace tecido::suites::ccd
