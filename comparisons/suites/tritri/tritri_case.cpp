#include "comparisons/suites/tritri/tritri_case.h"

#include "comparisons/suites/agreement/block_result.h"
#include "comparisons/suites/thread_cpu_time.h"

#include <stdexcept>

namespace tecido::suites::tritri {

namespace {

std::optional<agreement::Answer> as_answer(const std::optional<bool>& hit) {
  if (!hit) return std::nullopt;
  return agreement::Answer{*hit, 0.0};
}

/// The outside engine's answers to the whole block, and what they cost (see run_tritri_case).
agreement::EngineRun ask_outside(outside::OutsideEngine& engine, const std::vector<io::TriPair>& pairs) {
  std::vector<outside::TriTriQuery> queries;
  queries.reserve(pairs.size());
  for (const io::TriPair& p : pairs) queries.push_back({p.a, p.b});
  const double w0 = outside::door_seconds_on_this_thread(), t0 = thread_cpu_seconds();
  const std::vector<std::optional<bool>> got = engine.tri_tri(queries);
  agreement::EngineRun run;
  run.name = engine.name();
  // A process works outside this thread: its cost is the wall time of the round trips (its turn
  // only, not the wait for it) plus what encoding and decoding took here.
  run.seconds = thread_cpu_seconds() - t0 + (engine.is_process() ? outside::door_seconds_on_this_thread() - w0 : 0.0);
  if (got.size() != pairs.size()) throw std::runtime_error(engine.name() + " answered a different number of pairs");
  for (const auto& g : got) run.answers.push_back(as_answer(g));
  return run;
}

}  // namespace

io::Json run_tritri_case(std::uint64_t seed, const std::vector<Family>& families, const CaseRange& range,
                         const TriTriEngine& referee, const std::vector<TriTriEngine>& engines,
                         std::size_t max_disagreements, const std::vector<outside::OutsideEnginePtr>& outside) {
  const Family& family = families.at(range.family);
  std::vector<io::TriPair> pairs;
  pairs.reserve(static_cast<std::size_t>(range.count));
  for (long k = range.first; k < range.first + range.count; ++k) pairs.push_back(family_pair(seed, range.family, family, k));
  std::vector<agreement::Answer> truth(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::optional<bool> t = referee.test(pairs[i].a, pairs[i].b);
    if (!t) throw std::runtime_error("the referee gave no answer on " + pairs[i].id);
    truth[i].hit = *t;
  }
  std::vector<agreement::EngineRun> runs;
  for (const TriTriEngine& eng : engines) {
    agreement::EngineRun run;
    run.name = eng.name;
    run.answers.resize(pairs.size());
    const double t0 = thread_cpu_seconds();
    for (std::size_t i = 0; i < pairs.size(); ++i) run.answers[i] = as_answer(eng.test(pairs[i].a, pairs[i].b));
    run.seconds = thread_cpu_seconds() - t0;
    runs.push_back(std::move(run));
  }
  for (const outside::OutsideEnginePtr& eng : outside) runs.push_back(ask_outside(*eng, pairs));
  return agreement::block_result(truth, runs, range.first, max_disagreements);
}

}  // namespace tecido::suites::tritri
