#include "comparisons/suites/tritri/tritri_case.h"

#include "comparisons/suites/sweep.h"
#include "comparisons/suites/thread_cpu_time.h"
#include "comparisons/suites/tritri/agreement.h"

#include <stdexcept>

namespace tecido::suites::tritri {

namespace {

io::Json engine_json(const std::string& name, double seconds, const std::vector<char>& truth,
                     const std::vector<std::optional<bool>>& got, long first, std::size_t max_disagreements) {
  std::vector<long> disagree;
  const Tally t = count_agreement(truth, got, &disagree, first, max_disagreements);
  return {{"name", name}, {"seconds", num(seconds)}, {"tally", {t.agree, t.pairs, t.no_answer}}, {"disagree", disagree}};
}

/// The outside engine's answers to the whole block, and what they cost (see run_tritri_case).
std::vector<std::optional<bool>> ask_outside(outside::OutsideEngine& engine, const std::vector<io::TriPair>& pairs,
                                             double& seconds) {
  std::vector<outside::TriTriQuery> queries;
  queries.reserve(pairs.size());
  for (const io::TriPair& p : pairs) queries.push_back({p.a, p.b});
  const double w0 = outside::door_seconds_on_this_thread(), t0 = thread_cpu_seconds();
  std::vector<std::optional<bool>> got = engine.tri_tri(queries);
  // A process works outside this thread: its cost is the wall time of the round trips (its turn
  // only, not the wait for it) plus what encoding and decoding took here.
  seconds = thread_cpu_seconds() - t0 + (engine.is_process() ? outside::door_seconds_on_this_thread() - w0 : 0.0);
  if (got.size() != pairs.size()) throw std::runtime_error(engine.name() + " answered a different number of pairs");
  return got;
}

}  // namespace

io::Json run_tritri_case(std::uint64_t seed, const std::vector<Family>& families, const CaseRange& range,
                         const TriTriEngine& referee, const std::vector<TriTriEngine>& engines,
                         std::size_t max_disagreements, const std::vector<outside::OutsideEnginePtr>& outside) {
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
    out_engines.push_back(engine_json(eng.name, seconds, truth, got, range.first, max_disagreements));
  }
  for (const outside::OutsideEnginePtr& eng : outside) {
    double seconds = 0.0;
    const auto got = ask_outside(*eng, pairs, seconds);
    out_engines.push_back(engine_json(eng->name(), seconds, truth, got, range.first, max_disagreements));
  }
  return {{"intersecting", intersecting}, {"engines", out_engines}};
}

}  // namespace tecido::suites::tritri
