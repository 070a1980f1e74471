#include "comparisons/suites/selfcollision/selfcollision_report.h"

#include <fmt/format.h>

#include <algorithm>

namespace tecido::suites::selfcollision {

std::string method_markdown(const Settings& s, const std::vector<FrameSource>& sources,
                            const std::vector<SourceScore>& scores, const std::string& truth) {
  std::string md = fmt::format(
      "Frames recorded from running simulations, up to {} per source, at most {:.0f}% of them with a contact by "
      "core's detector and the rest without. Truth: `{}`. Precision = reported pairs that are true / reported (1 when "
      "nothing is reported); recall = true pairs reported / true pairs. Sources:\n\n",
      s.frames_per_source, 100.0 * s.contact_share, truth);
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const SourceScore& sc = scores[k];
    md += sc.error.empty()
              ? fmt::format("- `{}`: {}; {} triangles, {} frames, {} with a true contact, {} true pairs in all.\n",
                            sources[k].name, sources[k].about, sc.triangles, sc.frames, sc.frames_with_contact,
                            sc.true_pairs)
              : fmt::format("- `{}`: {}; failed: {}\n", sources[k].name, sources[k].about, sc.error);
  }
  return md + "\n";
}

namespace {
/// Every engine name in the scores, in first-seen order.
std::vector<std::string> engines_of(const std::vector<SourceScore>& scores) {
  std::vector<std::string> names;
  for (const SourceScore& sc : scores)
    for (const EngineScore& e : sc.engines)
      if (std::find(names.begin(), names.end(), e.engine) == names.end()) names.push_back(e.engine);
  return names;
}

const EngineScore* find(const SourceScore& sc, const std::string& engine) {
  for (const EngineScore& e : sc.engines)
    if (e.engine == engine) return &e;
  return nullptr;
}
}  // namespace

std::string score_table(const std::vector<FrameSource>& sources, const std::vector<SourceScore>& scores) {
  std::string md =
      "| engine | source | frames answered | reported | true positives | false positives | missed | precision | recall | "
      "ms per frame |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const std::string& name : engines_of(scores)) {
    for (std::size_t k = 0; k < sources.size(); ++k) {
      const EngineScore* e = find(scores[k], name);
      if (!e) continue;
      const PairAgreement& p = e->pairs;
      md += fmt::format("| {} | {} | {}/{} | {} | {} | {} | {} | {:.4f} | {:.4f} | {:.2f} |\n", name, sources[k].name,
                        e->answered, scores[k].frames, p.reported, p.true_positives, p.false_positives, p.missed,
                        p.precision(), p.recall(), scores[k].frames ? 1e3 * e->seconds / scores[k].frames : 0.0);
    }
  }
  return md;
}

namespace {
/// "on crumple: misses 2 of 55 true pairs, reports 1 that are not; ..." or "" when it matches everywhere.
std::string differences(const std::vector<FrameSource>& sources, const std::vector<SourceScore>& scores,
                        const std::string& engine) {
  std::string out;
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const EngineScore* e = find(scores[k], engine);
    if (!e) continue;
    std::string parts;
    if (e->answered < scores[k].frames) parts += fmt::format("leaves {} of {} frames unanswered", scores[k].frames - e->answered, scores[k].frames);
    if (e->pairs.missed) parts += fmt::format("{}misses {} of {} true pairs", parts.empty() ? "" : ", ", e->pairs.missed, e->pairs.true_positives + e->pairs.missed);
    if (e->pairs.false_positives) parts += fmt::format("{}reports {} pairs that do not intersect", parts.empty() ? "" : ", ", e->pairs.false_positives);
    if (!parts.empty()) out += fmt::format("{}on {}: {}", out.empty() ? "" : "; ", sources[k].name, parts);
  }
  return out;
}
}  // namespace

std::string conclusions_markdown(const std::vector<FrameSource>& sources, const std::vector<SourceScore>& scores,
                                 const std::string& truth) {
  std::string md = "From this table:\n\n";
  for (const std::string& name : engines_of(scores)) {
    if (name == truth) continue;
    const std::string diff = differences(sources, scores, name);
    md += fmt::format("- `{}` {}.\n", name, diff.empty() ? "matches the truth pair for pair on every frame" : diff);
  }
  for (std::size_t k = 0; k < sources.size(); ++k)
    if (!scores[k].error.empty()) md += fmt::format("- `{}` could not be recorded or scored: {}.\n", sources[k].name, scores[k].error);
  return md +
         "\n`core` is the box tree with the exact narrow phase, `core-brute` every pair with it. FCL's BVH returns every "
         "adjacent pair of a mesh against itself; its pairs are filtered to those sharing no vertex, and its leaf test "
         "is FCL's own floating-point triangle test.\n";
}

io::Json scores_json(const std::vector<FrameSource>& sources, const std::vector<SourceScore>& scores) {
  io::Json data = io::Json::object();
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const SourceScore& sc = scores[k];
    io::Json& js = data["sources"][sources[k].name];
    js = {{"frames", sc.frames}, {"frames_with_contact", sc.frames_with_contact}, {"true_pairs", sc.true_pairs},
          {"triangles", sc.triangles}};
    if (!sc.error.empty()) js["error"] = sc.error;
    for (const EngineScore& e : sc.engines) {
      const PairAgreement& p = e.pairs;
      data[e.engine][sources[k].name] = {
          {"frames", sc.frames},         {"answered", e.answered},   {"reported", p.reported},
          {"true_positives", p.true_positives}, {"false_positives", p.false_positives}, {"missed", p.missed},
          {"precision", p.precision()},  {"recall", p.recall()},
          {"ms_per_frame", sc.frames ? 1e3 * e.seconds / sc.frames : 0.0}};
    }
  }
  return data;
}

}  // namespace tecido::suites::selfcollision
