#include "comparisons/suites/ccd/family_statistics.h"

#include "comparisons/suites/sweep.h"

namespace tecido::suites::ccd {

io::Json family_result_json(const FamilyResult& r) {
  io::Json engines = io::Json::array();
  for (const EngineTally& e : r.engines)
    engines.push_back({{"engine", e.engine}, {"queries", e.queries}, {"no_answer", e.no_answer}, {"fn", e.fn},
                       {"fp", e.fp}, {"both_hit", e.both_hit}, {"max_toi_error", num(e.max_toi_error)},
                       {"sum_toi_error", num(e.sum_toi_error)}, {"toi_after", e.toi_after}, {"seconds", num(e.seconds)}});
  io::Json disagree = io::Json::array();
  for (const Disagreement& d : r.disagree) disagree.push_back({d.engine, d.query, d.truth});
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

FamilyResult family_result_from_json(const io::Json& j) {
  FamilyResult r;
  r.family = j.at("family").get<std::string>();
  r.queries = j.at("queries").get<long>();
  r.contacts = j.at("contacts").get<long>();
  r.known = j.at("known").get<long>();
  r.known_mismatch = j.at("known_mismatch").get<long>();
  r.unfiltered = j.at("unfiltered").get<long>();
  r.unfiltered_mismatch = j.at("unfiltered_mismatch").get<long>();
  for (const io::Json& e : j.at("engines")) {
    EngineTally t;
    t.engine = e.at("engine").get<std::string>();
    t.queries = e.at("queries").get<long>();
    t.no_answer = e.at("no_answer").get<long>();
    t.fn = e.at("fn").get<long>();
    t.fp = e.at("fp").get<long>();
    t.both_hit = e.at("both_hit").get<long>();
    t.max_toi_error = get_num(e.at("max_toi_error"));
    t.sum_toi_error = get_num(e.at("sum_toi_error"));
    t.toi_after = e.at("toi_after").get<long>();
    t.seconds = get_num(e.at("seconds"));
    r.engines.push_back(t);
  }
  for (const io::Json& d : j.at("disagree"))
    r.disagree.push_back({d.at(0).get<int>(), d.at(1).get<long>(), d.at(2).get<bool>()});
  return r;
}

}  // namespace tecido::suites::ccd
