#include "comparisons/suites/agreement/block_result.h"

#include "comparisons/suites/sweep.h"

#include <stdexcept>

namespace tecido::suites::agreement {

namespace {

io::Json disagreement_json(const Disagreement& d) {
  return {d.k, d.answer.hit, num(d.answer.t), d.truth.hit, num(d.truth.t)};
}

Disagreement disagreement_from_json(const io::Json& j, std::size_t engine, std::size_t family) {
  return {engine, family, j.at(0).get<long>(), {j.at(1).get<bool>(), get_num(j.at(2))},
          {j.at(3).get<bool>(), get_num(j.at(4))}};
}

Tally block_tally_from_json(const io::Json& j) {
  const io::Json& c = j.at("tally");
  Tally t;
  t.cases = c.at(0).get<long>();
  t.agree = c.at(1).get<long>();
  t.false_hits = c.at(2).get<long>();
  t.misses = c.at(3).get<long>();
  t.no_answer = c.at(4).get<long>();
  t.both_hit = c.at(5).get<long>();
  t.exact_path = c.at(6).get<long>();
  t.max_t_error = get_num(j.at("max_t_error"));
  return t;
}

}  // namespace

io::Json block_result(const std::vector<Answer>& truth, const std::vector<EngineRun>& runs, long first, std::size_t cap) {
  long hits = 0;
  for (const Answer& a : truth) hits += a.hit ? 1 : 0;
  io::Json engines = io::Json::array();
  for (const EngineRun& run : runs) {
    std::vector<Disagreement> disagree;
    Tally t = count_agreement(truth, run.answers, &disagree, first, cap);
    t.exact_path = run.exact_path;
    io::Json d = io::Json::array();
    for (const Disagreement& x : disagree) d.push_back(disagreement_json(x));
    engines.push_back({{"name", run.name},
                       {"seconds", num(run.seconds)},
                       {"tally", {t.cases, t.agree, t.false_hits, t.misses, t.no_answer, t.both_hit, t.exact_path}},
                       {"max_t_error", num(t.max_t_error)},
                       {"disagree", d}});
  }
  return {{"hits", hits}, {"engines", engines}};
}

void add_block(AgreementTable& table, const CaseRange& range, bool random, const io::Json& result) {
  const std::size_t f = range.family;
  if (const std::string* err = case_error(result)) {
    if (table.error[f].empty()) table.error[f] = *err;
    return;
  }
  table.hits[f] += result.at("hits").get<long>();
  const io::Json& engines = result.at("engines");
  if (engines.size() != table.engines.size()) throw std::runtime_error("agreement: a case result lists other engines");
  for (std::size_t e = 0; e < engines.size(); ++e) {
    const io::Json& je = engines[e];
    if (je.at("name").get<std::string>() != table.engines[e]) throw std::runtime_error("agreement: engines out of order");
    table.tally[f][e].add(block_tally_from_json(je));
    if (random) {
      table.random_seconds[e] += get_num(je.at("seconds"));
      table.random_timed[e] += range.count;
    }
    for (const io::Json& d : je.at("disagree")) table.disagree[e].push_back(disagreement_from_json(d, e, f));
  }
}

}  // namespace tecido::suites::agreement
