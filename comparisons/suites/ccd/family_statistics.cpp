#include "comparisons/suites/ccd/family_statistics.h"

#include "comparisons/suites/sweep.h"

namespace tecido::suites::ccd {

io::Json family_result_json(const FamilyResult& r) {
  io::Json engines = io::Json::array();
  for (const EngineTally& e : r.engines) {
    const agreement::Tally& t = e.tally;
    engines.push_back({{"engine", e.engine}, {"queries", t.cases}, {"no_answer", t.no_answer}, {"fn", t.misses},
                       {"fp", t.false_hits}, {"both_hit", t.both_hit}, {"max_toi_error", num(t.max_t_error)},
                       {"sum_toi_error", num(e.sum_toi_error)}, {"toi_after", e.toi_after}, {"max_toi_late", num(e.max_toi_late)},
                       {"seconds", num(e.seconds)}});
  }
  io::Json disagree = io::Json::array();
  for (const agreement::Disagreement& d : r.disagree)
    disagree.push_back({d.engine, d.k, d.answer.hit, num(d.answer.t), d.truth.hit, num(d.truth.t)});
  return {{"family", r.family},
          {"queries", r.queries},
          {"contacts", r.contacts},
          {"known", r.known},
          {"known_mismatch", r.known_mismatch},
          {"unfiltered", r.unfiltered},
          {"unfiltered_mismatch", r.unfiltered_mismatch},
          {"engines", engines},
          {"disagree", disagree}};
}

namespace {
EngineTally engine_tally_from_json(const io::Json& e) {
  EngineTally t;
  t.engine = e.at("engine").get<std::string>();
  t.tally.cases = e.at("queries").get<long>();
  t.tally.no_answer = e.at("no_answer").get<long>();
  t.tally.misses = e.at("fn").get<long>();
  t.tally.false_hits = e.at("fp").get<long>();
  t.tally.agree = t.tally.cases - t.tally.no_answer - t.tally.misses - t.tally.false_hits;
  t.tally.both_hit = e.at("both_hit").get<long>();
  t.tally.max_t_error = get_num(e.at("max_toi_error"));
  t.sum_toi_error = get_num(e.at("sum_toi_error"));
  t.toi_after = e.at("toi_after").get<long>();
  t.max_toi_late = get_num(e.at("max_toi_late"));
  t.seconds = get_num(e.at("seconds"));
  return t;
}
}  // namespace

FamilyResult family_result_from_json(const io::Json& j) {
  FamilyResult r;
  r.family = j.at("family").get<std::string>();
  r.queries = j.at("queries").get<long>();
  r.contacts = j.at("contacts").get<long>();
  r.known = j.at("known").get<long>();
  r.known_mismatch = j.at("known_mismatch").get<long>();
  r.unfiltered = j.at("unfiltered").get<long>();
  r.unfiltered_mismatch = j.at("unfiltered_mismatch").get<long>();
  for (const io::Json& e : j.at("engines")) r.engines.push_back(engine_tally_from_json(e));
  for (const io::Json& d : j.at("disagree"))
    r.disagree.push_back({d.at(0).get<std::size_t>(), 0, d.at(1).get<long>(), {d.at(2).get<bool>(), get_num(d.at(3))},
                          {d.at(4).get<bool>(), get_num(d.at(5))}});
  return r;
}

}  // namespace tecido::suites::ccd
