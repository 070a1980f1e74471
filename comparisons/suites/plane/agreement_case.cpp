#include "comparisons/suites/plane/agreement_case.h"

#include "comparisons/suites/agreement/block_result.h"
#include "comparisons/suites/thread_cpu_time.h"

#include <stdexcept>

namespace tecido::suites::plane {

namespace {
std::optional<agreement::Answer> plane_answer(const std::optional<SegmentPlaneHit>& h) {
  if (!h) return std::nullopt;
  return agreement::Answer{h->hit, h->t};
}
}  // namespace

io::Json run_agreement_case(std::uint64_t seed, const std::vector<Category>& categories, const CaseRange& range,
                            const SegmentPlaneEngine& referee, const std::vector<SegmentPlaneEngine>& engines,
                            std::size_t max_disagreements) {
  const Category& category = categories.at(range.family);
  std::vector<io::PlaneCase> cases;
  cases.reserve(static_cast<std::size_t>(range.count));
  for (long k = range.first; k < range.first + range.count; ++k)
    cases.push_back(category_case(seed, range.family, category, k));
  std::vector<agreement::Answer> truth(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::optional<SegmentPlaneHit> t = referee.test(cases[i].plane, cases[i].from, cases[i].to);
    if (!t) throw std::runtime_error("the referee gave no answer on " + cases[i].id);
    truth[i] = {t->hit, t->t};
  }
  std::vector<agreement::EngineRun> runs;
  for (const SegmentPlaneEngine& eng : engines) {
    agreement::EngineRun run;
    run.name = eng.name;
    run.answers.resize(cases.size());
    const std::uint64_t exact_before = segment_plane_exact_path_count();
    const double t0 = thread_cpu_seconds();
    for (std::size_t i = 0; i < cases.size(); ++i)
      run.answers[i] = plane_answer(eng.test(cases[i].plane, cases[i].from, cases[i].to));
    run.seconds = thread_cpu_seconds() - t0;
    run.exact_path = static_cast<long>(segment_plane_exact_path_count() - exact_before);
    runs.push_back(std::move(run));
  }
  return agreement::block_result(truth, runs, range.first, max_disagreements);
}

}  // namespace tecido::suites::plane
