#include "comparisons/suites/plane/agreement_case.h"

#include "comparisons/suites/plane/agreement.h"
#include "comparisons/suites/sweep.h"
#include "comparisons/suites/thread_cpu_time.h"

#include <stdexcept>

namespace tecido::suites::plane {

io::Json run_agreement_case(std::uint64_t seed, const std::vector<Category>& categories, const CaseRange& range,
                            const SegmentPlaneEngine& referee, const std::vector<SegmentPlaneEngine>& engines,
                            std::size_t max_disagreements) {
  const Category& category = categories.at(range.category);
  std::vector<io::PlaneCase> cases;
  cases.reserve(static_cast<std::size_t>(range.count));
  for (long k = range.first; k < range.first + range.count; ++k)
    cases.push_back(category_case(seed, range.category, category, k));
  std::vector<SegmentPlaneHit> truth(cases.size());
  long hits = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::optional<SegmentPlaneHit> t = referee.test(cases[i].plane, cases[i].from, cases[i].to);
    if (!t) throw std::runtime_error("the referee gave no answer on " + cases[i].id);
    truth[i] = *t;
    hits += t->hit ? 1 : 0;
  }
  io::Json out = io::Json::array();
  for (const SegmentPlaneEngine& eng : engines) {
    std::vector<std::optional<SegmentPlaneHit>> got(cases.size());
    const std::uint64_t exact_before = segment_plane_exact_path_count();
    const double t0 = thread_cpu_seconds();
    for (std::size_t i = 0; i < cases.size(); ++i) got[i] = eng.test(cases[i].plane, cases[i].from, cases[i].to);
    const double seconds = thread_cpu_seconds() - t0;
    std::vector<long> disagree;
    Tally t = count_agreement(truth, got, &disagree, range.first, max_disagreements);
    t.exact_path = static_cast<long>(segment_plane_exact_path_count() - exact_before);
    out.push_back({{"name", eng.name},
                   {"seconds", num(seconds)},
                   {"tally", {t.cases, t.agree, t.false_hits, t.misses, t.no_answer, t.both_hit, t.exact_path}},
                   {"max_t_error", num(t.max_t_error)},
                   {"disagree", disagree}});
  }
  return {{"hits", hits}, {"engines", out}};
}

}  // namespace tecido::suites::plane
