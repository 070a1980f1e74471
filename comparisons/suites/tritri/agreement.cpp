#include "comparisons/suites/tritri/agreement.h"

#include "comparisons/suites/sweep.h"

#include <cmath>
#include <stdexcept>

namespace tecido::suites::tritri {

void Tally::add(const Tally& t) {
  agree += t.agree;
  pairs += t.pairs;
  no_answer += t.no_answer;
}

double Tally::rate() const {
  return pairs > 0 ? static_cast<double>(agree) / static_cast<double>(pairs) : std::nan("");
}

Tally count_agreement(const std::vector<char>& truth, const std::vector<std::optional<bool>>& answers,
                      std::vector<long>* disagree, long first, std::size_t cap) {
  if (truth.size() != answers.size()) throw std::invalid_argument("count_agreement: truth and answers differ in length");
  Tally t;
  t.pairs = static_cast<long>(answers.size());
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (!answers[i]) {
      ++t.no_answer;
    } else if (*answers[i] == (truth[i] != 0)) {
      ++t.agree;
    } else if (disagree && disagree->size() < cap) {
      disagree->push_back(first + static_cast<long>(i));
    }
  }
  return t;
}

AgreementTable empty_table(std::size_t families, const std::vector<std::string>& engines) {
  AgreementTable t;
  t.engines = engines;
  t.error.assign(families, "");
  t.intersecting.assign(families, 0);
  t.tally.assign(families, std::vector<Tally>(engines.size()));
  t.random_seconds.assign(engines.size(), 0.0);
  t.random_pairs_timed.assign(engines.size(), 0);
  t.disagree.assign(engines.size(), {});
  return t;
}

void add_case(AgreementTable& table, const CaseRange& range, const std::vector<Family>& families,
              const io::Json& result) {
  const std::size_t f = range.family;
  if (const std::string* err = case_error(result)) {
    if (table.error[f].empty()) table.error[f] = *err;
    return;
  }
  table.intersecting[f] += result.at("intersecting").get<long>();
  const io::Json& engines = result.at("engines");
  if (engines.size() != table.engines.size()) throw std::runtime_error("tritri: a case result lists other engines");
  for (std::size_t e = 0; e < engines.size(); ++e) {
    const io::Json& je = engines[e];
    if (je.at("name").get<std::string>() != table.engines[e]) throw std::runtime_error("tritri: engines out of order");
    const io::Json& t = je.at("tally");
    table.tally[f][e].add(Tally{t.at(0).get<long>(), t.at(1).get<long>(), t.at(2).get<long>()});
    if (families[f].random) {
      table.random_seconds[e] += get_num(je.at("seconds"));
      table.random_pairs_timed[e] += range.count;
    }
    for (const auto& k : je.at("disagree")) table.disagree[e].push_back({e, f, k.get<long>()});
  }
}

double ns_per_pair(const AgreementTable& table, std::size_t e) {
  const long n = table.random_pairs_timed.at(e);
  return n > 0 ? 1e9 * table.random_seconds[e] / static_cast<double>(n) : std::nan("");
}

}  // namespace tecido::suites::tritri
