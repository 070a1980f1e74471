#include "comparisons/suites/plane/agreement.h"

#include "comparisons/suites/sweep.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tecido::suites::plane {

void Tally::add(const Tally& t) {
  cases += t.cases;
  agree += t.agree;
  false_hits += t.false_hits;
  misses += t.misses;
  no_answer += t.no_answer;
  if (t.both_hit > 0) max_t_error = both_hit > 0 ? std::max(max_t_error, t.max_t_error) : t.max_t_error;
  both_hit += t.both_hit;
  exact_path += t.exact_path;
}

double Tally::rate() const {
  return cases > 0 ? static_cast<double>(agree) / static_cast<double>(cases) : std::nan("");
}

Tally count_agreement(const std::vector<SegmentPlaneHit>& truth, const std::vector<std::optional<SegmentPlaneHit>>& answers,
                      std::vector<long>* disagree, long first, std::size_t cap) {
  if (truth.size() != answers.size()) throw std::invalid_argument("count_agreement: truth and answers differ in length");
  Tally t;
  t.cases = static_cast<long>(answers.size());
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const std::optional<SegmentPlaneHit>& a = answers[i];
    if (!a) {
      ++t.no_answer;
      continue;
    }
    if (a->hit == truth[i].hit) {
      ++t.agree;
      if (a->hit) {
        const double err = std::abs(a->t - truth[i].t);
        t.max_t_error = t.both_hit++ > 0 ? std::max(t.max_t_error, err) : err;
      }
      continue;
    }
    ++(a->hit ? t.false_hits : t.misses);
    if (disagree && disagree->size() < cap) disagree->push_back(first + static_cast<long>(i));
  }
  return t;
}

AgreementTable empty_table(std::size_t categories, const std::vector<std::string>& engines) {
  AgreementTable t;
  t.engines = engines;
  t.error.assign(categories, "");
  t.hits.assign(categories, 0);
  t.tally.assign(categories, std::vector<Tally>(engines.size()));
  t.random_seconds.assign(engines.size(), 0.0);
  t.random_cases_timed.assign(engines.size(), 0);
  t.disagree.assign(engines.size(), {});
  return t;
}

namespace {
Tally tally_from_json(const io::Json& j) {
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

void add_case(AgreementTable& table, const CaseRange& range, const std::vector<Category>& categories,
              const io::Json& result) {
  const std::size_t c = range.category;
  if (const std::string* err = case_error(result)) {
    if (table.error[c].empty()) table.error[c] = *err;
    return;
  }
  table.hits[c] += result.at("hits").get<long>();
  const io::Json& engines = result.at("engines");
  if (engines.size() != table.engines.size()) throw std::runtime_error("plane: a case result lists other engines");
  for (std::size_t e = 0; e < engines.size(); ++e) {
    const io::Json& je = engines[e];
    if (je.at("name").get<std::string>() != table.engines[e]) throw std::runtime_error("plane: engines out of order");
    table.tally[c][e].add(tally_from_json(je));
    if (categories.at(c).random) {
      table.random_seconds[e] += get_num(je.at("seconds"));
      table.random_cases_timed[e] += range.count;
    }
    for (const auto& k : je.at("disagree")) table.disagree[e].push_back({e, c, k.get<long>()});
  }
}

double ns_per_case(const AgreementTable& table, std::size_t e) {
  const long n = table.random_cases_timed.at(e);
  return n > 0 ? 1e9 * table.random_seconds[e] / static_cast<double>(n) : std::nan("");
}

GroupTally group_tally(const AgreementTable& table, const std::vector<Category>& categories, const CategoryGroup& group,
                       std::size_t e) {
  GroupTally g;
  for (const std::string& name : group.categories) {
    for (std::size_t c = 0; c < categories.size(); ++c) {
      if (categories[c].name != name) continue;
      if (!table.error[c].empty() && g.error.empty()) g.error = name + ": " + table.error[c];
      g.tally.add(table.tally[c][e]);
    }
  }
  return g;
}

}  // namespace tecido::suites::plane
