#include "comparisons/suites/ccd/family_case.h"

#include "comparisons/engines/ccd_engines.h"
#ifdef TECIDO_HAVE_REFERENCE
#include "reference/exact_ccd.h"
#endif

#include <cmath>
#include <stdexcept>

namespace tecido::suites::ccd {

#ifdef TECIDO_HAVE_REFERENCE

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

/// One engine on the block: timed answers, then the tally against the truth.
EngineTally tally_engine(const SuiteEngine& engine, int engine_index, const std::vector<KnownQuery>& queries,
                         const std::vector<ExactCcd>& truth, const Settings& s, FamilyResult& r) {
  EngineTally t;
  const std::vector<std::optional<CcdAnswer>> got = answer_block(engine, queries, t.seconds);
  t.engine = engine.name;
  t.queries = static_cast<long>(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const ExactCcd& e = truth[i];
    if (!got[i]) {
      ++t.no_answer;
      continue;
    }
    const CcdAnswer& a = *got[i];
    t.fn += e.hit && !a.hit;
    t.fp += a.hit && !e.hit;
    if (a.hit != e.hit && r.disagree.size() < s.max_disagreements)
      r.disagree.push_back({engine_index, static_cast<long>(i), e.hit});
    if (!(a.hit && e.hit)) continue;
    ++t.both_hit;
    const double err = std::fabs(a.toi - e.toi);
    t.max_toi_error = std::max(t.max_toi_error, err);
    t.sum_toi_error += err;
    // t* is e.toi when exact, otherwise strictly between the adjacent doubles toi_lo and toi_hi.
    t.toi_after += a.toi > (e.toi_exact ? e.toi : e.toi_lo);
  }
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
    r.engines.push_back(tally_engine(engines[k], static_cast<int>(k), queries, truth, s, r));
  return r;
}

#else

FamilyResult run_family(const std::string&, const std::vector<KnownQuery>&, const Settings&,
                        const std::vector<SuiteEngine>&) {
  throw std::logic_error("the ccd suite needs the exact referee (reference build)");
}

#endif

}  // namespace tecido::suites::ccd
