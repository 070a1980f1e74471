#include "comparisons/suites/selfcollision/frame_disagreements.h"

#include "comparisons/suites/selfcollision/frame_sources.h"
#include "comparisons/suites/sweep.h"
#include "comparisons/view/base64.h"

#include <algorithm>

namespace tecido::suites::selfcollision {

namespace {

using PairList = std::vector<std::array<int, 2>>;

PairList first(const PairList& pairs, std::size_t cap) {
  return PairList(pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(std::min(cap, pairs.size())));
}

bool has_frame(const KeptDisagreements& k, int frame) {
  for (const auto& f : k.frames)
    if (f.first == frame) return true;
  return false;
}

}  // namespace

void KeptDisagreements::note(const Settings& s, const std::string& engine, const FrameSet& set, int frame,
                             const PairList& got, const PairList& truth) {
  PairDifference d = pair_difference(got, truth);
  if (d.missed.empty() && d.extra.empty()) return;
  ++found;
  if (kept.size() >= s.max_entries_per_source) return;
  const Frame& f = set.frames.at(static_cast<std::size_t>(frame));
  kept.push_back({engine, frame, f.time, {first(d.missed, s.max_pairs_per_list), first(d.extra, s.max_pairs_per_list)},
                  static_cast<long>(d.missed.size()), static_cast<long>(d.extra.size())});
  if (triangles.empty()) triangles = set.triangles;
  if (!has_frame(*this, frame)) frames.emplace_back(frame, f);
}

io::Json kept_json(const KeptDisagreements& k) {
  io::Json entries = io::Json::array(), frames = io::Json::array();
  for (const FrameDisagreement& d : k.kept)
    entries.push_back({{"engine", d.engine}, {"frame", d.frame}, {"time", num(d.time)}, {"missed", d.pairs.missed},
                       {"extra", d.pairs.extra}, {"missed_count", d.missed}, {"extra_count", d.extra}});
  for (const auto& [index, f] : k.frames) frames.push_back({{"frame", index}, {"time", num(f.time)}, {"x", vec3s_json(f.x)}});
  return {{"found", k.found}, {"entries", entries}, {"triangles", k.triangles}, {"frames", frames}};
}

KeptDisagreements kept_from_json(const io::Json& j) {
  KeptDisagreements k;
  k.found = j.at("found").get<long>();
  for (const io::Json& e : j.at("entries"))
    k.kept.push_back({e.at("engine").get<std::string>(), e.at("frame").get<int>(), get_num(e.at("time")),
                      {e.at("missed").get<PairList>(), e.at("extra").get<PairList>()}, e.at("missed_count").get<long>(),
                      e.at("extra_count").get<long>()});
  k.triangles = j.at("triangles").get<std::vector<std::array<int, 3>>>();
  for (const io::Json& f : j.at("frames"))
    k.frames.emplace_back(f.at("frame").get<int>(), Frame{get_num(f.at("time")), vec3s_from_json(f.at("x"))});
  return k;
}

io::Json disagreements_json(const std::vector<FrameSource>& sources, const std::vector<KeptDisagreements>& kept,
                            const std::string& truth, const Settings& s) {
  io::Json out_sources = io::Json::array(), entries = io::Json::array();
  for (std::size_t k = 0; k < sources.size() && k < kept.size(); ++k) {
    const std::string& name = sources[k].name;
    io::Json frames = io::Json::array();
    for (const auto& [index, f] : kept[k].frames)
      frames.push_back({{"frame", index}, {"time", f.time}, {"x", vec3s_json(f.x)}});
    out_sources.push_back(
        {{"source", name}, {"entries_found", kept[k].found}, {"triangles", kept[k].triangles}, {"frames", frames}});
    for (const FrameDisagreement& d : kept[k].kept)
      entries.push_back({{"id", d.engine + ":" + name + "/" + std::to_string(d.frame)},
                         {"engine", d.engine},
                         {"source", name},
                         {"frame", d.frame},
                         {"time", d.time},
                         {"missed", d.pairs.missed},
                         {"extra", d.pairs.extra},
                         {"missed_count", d.missed},
                         {"extra_count", d.extra}});
  }
  return {{"truth", truth},
          {"max_entries_per_source", s.max_entries_per_source},
          {"max_pairs_per_list", s.max_pairs_per_list},
          {"sources", out_sources},
          {"entries", entries}};
}

io::Json disagreements_page_doc(const io::Json& doc) {
  io::Json page = doc;
  for (io::Json& src : page.at("sources")) {
    std::vector<std::uint32_t> tris;
    for (const io::Json& t : src.at("triangles"))
      for (const io::Json& v : t) tris.push_back(v.get<std::uint32_t>());
    src["triangles"] = view::uint32_base64(tris);
    for (io::Json& f : src.at("frames")) {
      std::vector<float> x;
      for (const io::Json& c : f.at("x")) x.push_back(static_cast<float>(get_num(c)));
      f["x"] = view::float32_base64(x);
    }
  }
  return page;
}

}  // namespace tecido::suites::selfcollision
