#include "comparisons/suites/tritri/tritri_case.h"

#include "comparisons/suites/sweep.h"
#include "comparisons/suites/thread_cpu_time.h"
#include "comparisons/suites/tritri/agreement.h"

#include <stdexcept>

namespace tecido::suites::tritri {

io::Json run_tritri_case(std::uint64_t seed, const std::vector<Family>& families, const CaseRange& range,
                         const TriTriEngine& referee, const std::vector<TriTriEngine>& engines,
                         std::size_t max_disagreements) {
  const Family& family = families.at(range.family);
  std::vector<io::TriPair> pairs;
  pairs.reserve(static_cast<std::size_t>(range.count));
  for (long k = range.first; k < range.first + range.count; ++k) pairs.push_back(family_pair(seed, range.family, family, k));
  std::vector<char> truth(pairs.size());
  long intersecting = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::optional<bool> t = referee.test(pairs[i].a, pairs[i].b);
    if (!t) throw std::runtime_error("the referee gave no answer on " + pairs[i].id);
    truth[i] = *t;
    intersecting += *t ? 1 : 0;
  }
  io::Json out_engines = io::Json::array();
  for (const TriTriEngine& eng : engines) {
    std::vector<std::optional<bool>> got(pairs.size());
    const double t0 = thread_cpu_seconds();
    for (std::size_t i = 0; i < pairs.size(); ++i) got[i] = eng.test(pairs[i].a, pairs[i].b);
    const double seconds = thread_cpu_seconds() - t0;
    std::vector<long> disagree;
    const Tally t = count_agreement(truth, got, &disagree, range.first, max_disagreements);
    out_engines.push_back({{"name", eng.name},
                           {"seconds", num(seconds)},
                           {"tally", {t.agree, t.pairs, t.no_answer}},
                           {"disagree", disagree}});
  }
  return {{"intersecting", intersecting}, {"engines", out_engines}};
}

}  // namespace tecido::suites::tritri
