#include "comparisons/suites/agreement/tally.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tecido::suites::agreement {

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

Tally count_agreement(const std::vector<Answer>& truth, const std::vector<std::optional<Answer>>& answers,
                      std::vector<Disagreement>* disagree, long first, std::size_t cap) {
  if (truth.size() != answers.size()) throw std::invalid_argument("count_agreement: truth and answers differ in length");
  Tally t;
  t.cases = static_cast<long>(answers.size());
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const std::optional<Answer>& a = answers[i];
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
    if (disagree && disagree->size() < cap) disagree->push_back({0, 0, first + static_cast<long>(i), *a, truth[i]});
  }
  return t;
}

}  // namespace tecido::suites::agreement
