#include "comparisons/suites/selfcollision/selfcollision_case.h"

#include "comparisons/suites/sweep.h"
#include "comparisons/suites/thread_cpu_time.h"

#include <stdexcept>

namespace tecido::suites::selfcollision {

namespace {
EngineScore score_engine(const SelfCollisionEngine& eng, const FrameSet& set,
                         const std::vector<std::vector<TrianglePair>>& truth, const Settings& s, KeptDisagreements& kept) {
  EngineScore e;
  e.engine = eng.name;
  for (std::size_t i = 0; i < set.frames.size(); ++i) {
    const double t0 = thread_cpu_seconds();
    const auto got = eng.pairs(set.frames[i].x, set.triangles);
    e.seconds += thread_cpu_seconds() - t0;
    if (!got) continue;
    ++e.answered;
    e.pairs.add(*got, truth[i]);
    kept.note(s, e.engine, set, static_cast<int>(i), *got, truth[i]);
  }
  return e;
}

/// A narrow phase that accepts every pair: the detector then returns its broad phase's candidates.
bool every_pair(const Triangle&, const Triangle&) { return true; }

EngineScore score_outside(outside::OutsideEngine& eng, const FrameSet& set,
                          const std::vector<std::vector<TrianglePair>>& truth, const Settings& s, KeptDisagreements& kept) {
  EngineScore e;
  e.engine = eng.name();
  for (std::size_t i = 0; i < set.frames.size(); ++i) {
    const auto got = outside_pairs(eng, set.frames[i].x, set.triangles, e.seconds);
    if (!got) continue;
    ++e.answered;
    e.pairs.add(*got, truth[i]);
    kept.note(s, e.engine, set, static_cast<int>(i), *got, truth[i]);
  }
  return e;
}
}  // namespace

std::optional<std::vector<TrianglePair>> outside_pairs(outside::OutsideEngine& engine, const std::vector<Vec3>& x,
                                                       const std::vector<std::array<int, 3>>& triangles,
                                                       double& seconds) {
  const double w0 = outside::door_seconds_on_this_thread(), t0 = thread_cpu_seconds();
  const std::vector<TrianglePair> candidates = self_collision_pairs(x, triangles, &every_pair);
  std::vector<outside::TriTriQuery> queries;
  queries.reserve(candidates.size());
  const auto tri = [&](int k) {
    const auto& t = triangles[static_cast<std::size_t>(k)];
    return Triangle{x[static_cast<std::size_t>(t[0])], x[static_cast<std::size_t>(t[1])], x[static_cast<std::size_t>(t[2])]};
  };
  for (const TrianglePair& p : candidates) queries.push_back({tri(p[0]), tri(p[1])});
  const auto got = queries.empty() ? std::vector<std::optional<bool>>{} : engine.tri_tri(queries);
  seconds += thread_cpu_seconds() - t0 + (engine.is_process() ? outside::door_seconds_on_this_thread() - w0 : 0.0);
  if (got.size() != queries.size()) throw std::runtime_error(engine.name() + " answered a different number of pairs");
  std::vector<TrianglePair> pairs;
  for (std::size_t k = 0; k < got.size(); ++k) {
    if (!got[k]) return std::nullopt;
    if (*got[k]) pairs.push_back(candidates[k]);
  }
  return pairs;  // candidates are sorted, so these are too
}

SourceScore score_source(const FrameSource& source, const Settings& s, const std::string& data_dir,
                         const SelfCollisionEngine& truth, const std::vector<SelfCollisionEngine>& engines,
                         const std::vector<outside::OutsideEnginePtr>& outside) {
  const FrameSet set = source.record(s, data_dir);
  SourceScore out;
  out.frames = static_cast<long>(set.frames.size());
  out.triangles = static_cast<long>(set.triangles.size());
  std::vector<std::vector<TrianglePair>> true_pairs;
  for (const Frame& f : set.frames) {
    auto t = truth.pairs(f.x, set.triangles);
    if (!t) throw std::runtime_error("the truth engine " + truth.name + " gave no answer at t = " + std::to_string(f.time));
    out.true_pairs += static_cast<long>(t->size());
    out.frames_with_contact += t->empty() ? 0 : 1;
    true_pairs.push_back(std::move(*t));
  }
  for (const SelfCollisionEngine& eng : engines)
    out.engines.push_back(score_engine(eng, set, true_pairs, s, out.disagreements));
  for (const outside::OutsideEnginePtr& eng : outside)
    out.engines.push_back(score_outside(*eng, set, true_pairs, s, out.disagreements));
  return out;
}

io::Json source_score_json(const SourceScore& s) {
  io::Json engines = io::Json::array();
  for (const EngineScore& e : s.engines) {
    const PairAgreement& p = e.pairs;
    engines.push_back({{"engine", e.engine}, {"answered", e.answered}, {"reported", p.reported},
                       {"true_positives", p.true_positives}, {"false_positives", p.false_positives},
                       {"missed", p.missed}, {"seconds", num(e.seconds)}});
  }
  return {{"frames", s.frames}, {"frames_with_contact", s.frames_with_contact}, {"true_pairs", s.true_pairs},
          {"triangles", s.triangles}, {"engines", engines}, {"disagreements", kept_json(s.disagreements)}};
}

SourceScore source_score_from_json(const io::Json& j) {
  SourceScore s;
  if (const std::string* err = case_error(j)) {
    s.error = *err;
    return s;
  }
  s.frames = j.at("frames").get<long>();
  s.frames_with_contact = j.at("frames_with_contact").get<long>();
  s.true_pairs = j.at("true_pairs").get<long>();
  s.triangles = j.at("triangles").get<long>();
  for (const io::Json& je : j.at("engines")) {
    EngineScore e;
    e.engine = je.at("engine").get<std::string>();
    e.answered = je.at("answered").get<long>();
    e.pairs = {je.at("reported").get<long>(), je.at("true_positives").get<long>(), je.at("false_positives").get<long>(),
               je.at("missed").get<long>()};
    e.seconds = get_num(je.at("seconds"));
    s.engines.push_back(std::move(e));
  }
  s.disagreements = kept_from_json(j.at("disagreements"));
  return s;
}

}  // namespace tecido::suites::selfcollision
