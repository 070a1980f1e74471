#include "comparisons/suites/forced_contact/document.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/io/provenance.h"
#include "comparisons/suites/self_contact/document.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::forced_contact {

namespace {

using OJson = nlohmann::ordered_json;

constexpr const char* kMultiplicity =
    "four claims, each decided on its own 95% interval; no adjustment is applied (Holm's step-down over the four "
    "claims would make each rule stricter; it plugs in where claims.cpp decides a verdict)";

OJson number(double x) {
  if (std::isnan(x)) return nullptr;
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}
OJson interval(const Interval& ci) { return OJson::array({number(ci.lo), number(ci.hi)}); }

const char* response_name(const Settings& s, int r) { return self_collision_response_name(s.responses[r]); }

OJson cells_json(const Plan& plan, const Findings& f) {
  OJson cells = OJson::array();
  for (std::size_t h = 0; h < f.outcomes.size(); ++h)
    for (std::size_t r = 0; r < f.outcomes[h].size(); ++r) {
      const CellOutcome& c = f.outcomes[h][r];
      cells.push_back({{"hold", plan.settings.holds[h]}, {"response", response_name(plan.settings, r)},
                       {"runs", c.runs}, {"unstable", c.unstable}, {"forced", c.forced},
                       {"held_pairs", number(c.held_pairs)}, {"recovered", c.recovered},
                       {"recovered_ci95", interval(c.share_ci)}, {"median", number(c.median)},
                       {"median_ci95", interval(c.median_ci)}, {"restricted_mean", number(c.restricted.mean)},
                       {"restricted_ci95", interval(c.restricted.ci95)}, {"free_at_end", c.free_at_end},
                       {"mean_series", c.mean_series}});
    }
  return cells;
}

OJson runs_json(const Plan& plan, const std::vector<io::Json>& results) {
  OJson runs = OJson::array();
  for (std::size_t k = 0; k < results.size(); ++k) {
    const CaseSpec& c = plan.cases[k];
    OJson j = {{"hold", plan.settings.holds[c.hold]}, {"response", response_name(plan.settings, c.response)}, {"seed", c.seed}};
    if (const std::string* e = case_error(results[k])) {
      j["error"] = *e;
    } else {
      for (const auto& [key, value] : results[k].items())
        if (key != "case") j[key] = value;
    }
    runs.push_back(j);
  }
  return runs;
}

OJson settings_json(const Settings& s) {
  OJson responses = OJson::array();
  for (std::size_t r = 0; r < s.responses.size(); ++r) responses.push_back(response_name(s, r));
  return {{"holds", s.holds}, {"responses", responses}, {"after_release", s.after_release}, {"dwell", s.dwell},
          {"censor", censor_time(s)}, {"sample", s.sample}, {"bootstrap", s.bootstrap},
          {"recovers_share", s.recovers_share}, {"hold_margin", s.hold_margin}};
}

std::string seconds(double x) {
  if (std::isnan(x)) return "n/a";
  if (std::isinf(x)) return "not reached";
  return fmt::format("{:.2f}", x);
}
std::string seconds_interval(const Interval& ci) { return fmt::format("[{}, {}]", seconds(ci.lo), seconds(ci.hi)); }
std::string share_interval(const Interval& ci) {
  return std::isnan(ci.lo) ? "n/a" : fmt::format("[{:.2f}, {:.2f}]", ci.lo, ci.hi);
}

std::string claims_section(const Findings& f) {
  std::string md = "## Claims\n\n| claim | statement | ours | 95% interval | n | verdict |\n|---|---|---|---|---|---|\n";
  for (const Claim& c : f.claims)
    md += fmt::format("| `{}` | {} | {} | {} | {} | **{}**{} |\n", c.id, c.statement,
                      c.unit == "share of runs" ? fmt::format("{:.3f}", c.observed) : fmt::format("{:+.3f} s", c.observed),
                      c.unit == "share of runs" ? share_interval(c.ci95) : seconds_interval(c.ci95), c.n,
                      self_contact::verdict_name(c.verdict), c.reason.empty() ? "" : " (" + c.reason + ")");
  md += "\nRules (stated before the data, comparisons/suites/forced_contact/claims.h):\n\n";
  for (const Claim& c : f.claims)
    md += fmt::format("- `{}` ({}): {}{}\n", c.id, c.unit, c.rule, c.observed_text.empty() ? "" : " Found: " + c.observed_text + ".");
  return md + fmt::format("\nMultiplicity: {}.\n\n", kMultiplicity);
}

std::string cells_section(const Plan& plan, const Findings& f) {
  std::string md = fmt::format(
      "## Recovery per response and hold\n\nForced: runs with an intersecting pair at the last held frame (exact test). "
      "Recovered: free of self-intersection from some frame on, at least {} s before the horizon ({} s after release; "
      "censored at {} s), Wilson 95% interval. Median: censored (Kaplan-Meier) median time after release, 95% "
      "percentile bootstrap interval ({} resamples). Restricted mean: each run's recovery time, {} s when it did not "
      "recover, 95% t interval.\n\n"
      "| response | hold [s] | runs | forced | pairs held | recovered | 95% | median [s] | 95% | restricted mean [s] | 95% | free at end |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      plan.settings.dwell, plan.settings.after_release, censor_time(plan.settings), plan.settings.bootstrap,
      censor_time(plan.settings));
  for (std::size_t r = 0; r < plan.settings.responses.size(); ++r)
    for (std::size_t h = 0; h < plan.settings.holds.size(); ++h) {
      const CellOutcome& c = f.outcomes[h][r];
      md += fmt::format("| {} | {} | {}{} | {} | {:.1f} | {} | {} | {} | {} | {} | {} | {} |\n", response_name(plan.settings, r),
                        plan.settings.holds[h], c.runs, c.unstable ? fmt::format(" ({} unstable)", c.unstable) : "", c.forced,
                        c.held_pairs, c.recovered, share_interval(c.share_ci), seconds(c.median), seconds_interval(c.median_ci),
                        seconds(c.restricted.mean), seconds_interval(c.restricted.ci95), c.free_at_end);
    }
  return md + "\n";
}

std::string plot_data(const Plan& plan, const Findings& f, std::size_t h) {
  std::string dat = "# time [s]";
  for (std::size_t r = 0; r < plan.settings.responses.size(); ++r) dat += std::string(" ") + response_name(plan.settings, r);
  dat += "  (mean intersecting pairs over the runs)\n";
  std::size_t len = 0;
  for (const CellOutcome& c : f.outcomes[h]) len = std::max(len, c.mean_series.size());
  for (std::size_t k = 0; k < len; ++k) {
    dat += fmt::format("{:.17g}", static_cast<double>(k + 1) * plan.settings.sample);
    for (const CellOutcome& c : f.outcomes[h])
      dat += k < c.mean_series.size() ? fmt::format(" {:.17g}", c.mean_series[k]) : std::string(" ?");
    dat += "\n";
  }
  return dat;
}

std::string plots_section(const Plan& plan, const Findings& f) {
  const std::string& dir = plan.opt.out_dir;
  if (dir.empty()) return "";
  std::string md = "## Intersecting pairs over time\n\n";
  const bool gnuplot = io::gnuplot_available();
  for (std::size_t h = 0; h < plan.settings.holds.size(); ++h) {
    const std::string name = fmt::format("forced_pairs_{}", h);
    io::write_file_atomic(dir + "/" + name + ".dat", plot_data(plan, f, h));
    const Timeline t = timeline(plan.scene, plan.settings.holds[h], plan.settings.after_release);
    std::string plot = "plot ";
    for (std::size_t r = 0; r < plan.settings.responses.size(); ++r)
      plot += fmt::format("{}'{}.dat' using 1:{} with lines lw 2 title '{}'", r ? ", " : "", name, r + 2,
                          response_name(plan.settings, r));
    const std::string script = fmt::format(
        "set terminal svg size 1000,420 dynamic font 'sans,11'\nset output '{0}.svg'\nset datafile missing '?'\nset grid\n"
        "set key outside right\nset xlabel 'time [s]'\nset ylabel 'intersecting triangle pairs (mean over runs)'\n"
        "set title 'hold {1} s: grips take hold at {2} s, let go at {3} s'\nset arrow from {2},graph 0 to {2},graph 1 nohead dt 2\n"
        "set arrow from {3},graph 0 to {3},graph 1 nohead dt 2\n{4}\n",
        name, plan.settings.holds[h], static_cast<double>(t.grip) * plan.scene.dt,
        static_cast<double>(t.release) * plan.scene.dt, plot);
    if (gnuplot && io::run_gnuplot(dir, name, script))
      md += fmt::format("![hold {} s: mean intersecting pairs against time per response]({}.svg)\n\n", plan.settings.holds[h], name);
  }
  if (!gnuplot) md += "gnuplot not found: the data are in forced_pairs_<hold index>.dat.\n\n";
  return md;
}

std::string method_section(const Plan& plan) {
  return fmt::format(
      "## Method\n\n{} runs per (response, hold), run s starting from the offsets of substream({}, s) whatever the "
      "response and hold, so the claims' differences are paired by s. After every step the exact discrete test (core's "
      "tri_tri_intersect on every non-adjacent triangle pair) counts the intersecting pairs; counting never changes "
      "the run. Command: `{}`.\n",
      plan.settings.seeds, plan.scene.seed, command_line(plan.opt));
}

}  // namespace

std::string experiment_json(const Plan& plan, const Findings& f, const std::vector<io::Json>& results) {
  OJson doc;
  doc["experiment"] = "forced-contact";
  doc["command"] = command_line(plan.opt);
  doc["tecido"] = OJson::parse(io::provenance_json().dump());
  doc["quick"] = plan.opt.quick;
  doc["seeds"] = plan.settings.seeds;
  doc["settings"] = settings_json(plan.settings);
  doc["scene"] = OJson::parse(scene_json(plan.scene).dump());
  doc["scene_note"] = scene_note(plan.scene);
  OJson claims = OJson::array();
  for (const Claim& c : f.claims) claims.push_back(self_contact::claim_json(c));
  doc["claims"] = claims;
  doc["multiplicity"] = kMultiplicity;
  doc["cells"] = cells_json(plan, f);
  doc["errors"] = f.errors;
  doc["runs"] = runs_json(plan, results);
  return doc.dump(2) + "\n";
}

std::string experiment_markdown(const Plan& plan, const Findings& f) {
  std::string md = "# Forced self-contact: history-based response against GIA\n\n"
                   "The seed's argument for Global Intersection Analysis (3.1.3, fig. 16): a response that decides each "
                   "pair's side from its history comes to keep the wrong side when a contact is forced and cannot be "
                   "undone at once; GIA looks only at the current frame. `" + command_line(plan.opt) + "`.\n\n";
  md += claims_section(f);
  md += "## Scene\n\n" + scene_note(plan.scene) + "\n";
  md += cells_section(plan, f);
  md += plots_section(plan, f);
  if (!f.errors.empty()) {
    md += "## Errors\n\n";
    for (const auto& e : f.errors) md += "- " + e + "\n";
    md += "\n";
  }
  return md + method_section(plan);
}

}  // namespace tecido::suites::forced_contact
