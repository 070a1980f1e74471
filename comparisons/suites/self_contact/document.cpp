#include "comparisons/suites/self_contact/document.h"

#include "comparisons/io/provenance.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::self_contact {

namespace {

using OJson = nlohmann::ordered_json;

OJson number(double x) { return std::isfinite(x) ? OJson(x) : OJson(nullptr); }
OJson interval(const Interval& i) { return OJson::array({number(i.lo), number(i.hi)}); }
OJson from(const io::Json& j) { return OJson::parse(j.dump()); }

OJson cell_values(const Cell& c) {
  return {{"index", c.index}, {"elasticity", c.elasticity}, {"dt", c.dt}, {"wind", c.wind},
          {"mode", c.mode == 0 ? OJson("none") : OJson(c.mode)}};
}

OJson stats_json(const CellStats& c) {
  return {{"mean", number(c.s.mean)}, {"sd", number(c.s.sd)}, {"ci95", interval(c.s.ci95)}, {"pi95", interval(c.s.pi95)},
          {"n", c.s.n}, {"seed_percentile", number(c.seed_percentile)},
          {"seed_in_pi95", std::isnan(c.seed_value) || std::isnan(c.s.pi95.lo) ? OJson(nullptr) : OJson(c.s.pi95.contains(c.seed_value))}};
}

OJson cells_json(const Plan& plan, const Findings& f) {
  std::vector<std::vector<CellStats>> by_d;
  for (std::size_t d = 0; d < plan.detectors.size(); ++d) by_d.push_back(baseline_cells(plan, f, d));
  OJson out = OJson::array();
  for (int c = 0; c < CellGrid::kCells; ++c) {
    OJson j = cell_values(CellGrid::cell(c));
    j["role"] = plan.calibration.fit[c] ? "fit" : "prediction";
    j["seed_value"] = number(plan.seed.share[c]);
    j["detector"] = contact_test_name(plan.detectors[0]);
    const OJson first = stats_json(by_d[0][c]);
    for (auto it = first.begin(); it != first.end(); ++it) j[it.key()] = it.value();
    OJson by = OJson::object();
    for (std::size_t d = 0; d < by_d.size(); ++d) by[contact_test_name(plan.detectors[d])] = stats_json(by_d[d][c]);
    j["by_detector"] = by;
    out.push_back(j);
  }
  return out;
}

OJson run_entry(const Plan& plan, const CaseSpec& c, const io::Json& result) {
  OJson j = cell_values(CellGrid::cell(c.cell));
  j["seed"] = c.seed;
  if (const std::string* err = case_error(result)) {
    j["error"] = *err;
    return j;
  }
  const RunResult r = run_from_json(result);
  OJson by = OJson::object();
  for (std::size_t d = 0; d < plan.detectors.size(); ++d) {
    const SelfContactCount& k = r.counts[d];
    by[contact_test_name(plan.detectors[d])] = {{"contact_frames", k.contact_frames}, {"share", number(share(r, d))},
                                                {"pairs", k.pairs}, {"max_pairs", k.max_pairs}};
  }
  j["frames"] = r.counts[0].frames;
  for (const char* key : {"contact_frames", "share", "pairs", "max_pairs"}) j[key] = by[contact_test_name(plan.detectors[0])][key];
  j["status"] = r.status;
  j["unstable_at_step"] = r.unstable_at_step >= 0 ? OJson(r.unstable_at_step) : OJson(nullptr);
  j["by_detector"] = by;
  return j;
}

OJson runs_json(const Plan& plan, const std::vector<io::Json>& results) {
  OJson out = OJson::array();
  for (std::size_t k = 0; k < plan.cases.size(); ++k)
    if (plan.cases[k].kind == CaseSpec::Run && plan.cases[k].variant == 0) out.push_back(run_entry(plan, plan.cases[k], results[k]));
  return out;
}

OJson agreement_json(const Agreement& a) {
  return {{"cells", a.cells}, {"seed_inside_pi95", a.inside_pi95}, {"mean_abs_diff", number(a.mean_abs_diff)},
          {"rms_diff", number(a.rms_diff)}, {"correlation", number(a.correlation)}};
}

OJson calibration_section(const Plan& plan, const Findings& f) {
  const auto cells = baseline_cells(plan, f, 0);
  OJson fit = OJson::array();
  for (int c = 0; c < CellGrid::kCells; ++c)
    if (plan.calibration.fit[c]) fit.push_back(c);
  return {{"file", plan.calibration.file},
          {"fitted", {{"air_drag", plan.calibration.air_drag}, {"swirl_rate", plan.calibration.swirl_rate}}},
          {"fit_cells", fit},
          {"agreement",
           {{"detector", contact_test_name(plan.detectors[0])},
            {"fit", agreement_json(agreement(cells, plan.calibration.fit, true))},
            {"prediction", agreement_json(agreement(cells, plan.calibration.fit, false))}}},
          {"record", from(plan.calibration.doc)}};
}

OJson sensitivity_section(const Plan& plan, const Findings& f) {
  OJson variants = OJson::array(), rows = OJson::array(), robust = OJson::array();
  for (const Variant& v : plan.variants)
    variants.push_back({{"id", v.id}, {"choice", v.choice}, {"about", v.about}, {"interpretation", from(interpretation_json(v.in))}});
  for (const SensitivityRow& r : f.rows) {
    OJson verdicts = OJson::object();
    for (const Claim& c : r.claims) verdicts[c.id] = verdict_name(c.verdict);
    rows.push_back({{"variant", r.variant}, {"detector", r.detector}, {"verdicts", verdicts}});
  }
  for (const Robustness& r : f.robustness)
    robust.push_back({{"id", r.id}, {"status", r.status}, {"reproduced", r.reproduced}, {"not_reproduced", r.not_reproduced},
                      {"inconclusive", r.inconclusive}});
  return {{"variants", variants}, {"rows", rows}, {"robustness", robust}};
}

std::string robustness_of(const Findings& f, const std::string& id) {
  for (const Robustness& r : f.robustness)
    if (r.id == id) return r.status;
  return "";
}

OJson held_out_json(const HeldOut& h) {
  if (!h.computed) return nullptr;
  return {{"observed", number(h.observed)},     {"ci95", interval(h.ci95)},
          {"n", h.n},                           {"p_support_holm", number(h.p_support_holm)},
          {"p_refute_holm", number(h.p_refute_holm)}, {"verdict", verdict_name(h.verdict)},
          {"reason", h.reason},                 {"observed_text", h.observed_text}};
}

OJson figures_json(const Claim& c) {
  OJson out = OJson::object();
  for (const auto& [name, value] : c.figures) out[name] = number(value);
  return out;
}

}  // namespace

nlohmann::ordered_json claim_json(const Claim& c) {
  return {{"id", c.id},
          {"detector", c.detector.empty() ? OJson(nullptr) : OJson(c.detector)},
          {"statement", c.statement},
          {"seed", number(c.seed)},
          {"seed_text", c.seed_text},
          {"observed", number(c.observed)},
          {"observed_text", c.observed_text},
          {"ci95", interval(c.ci95)},
          {"n", c.n},
          {"unit", c.unit},
          {"verdict", verdict_name(c.verdict)},
          {"rule", c.rule},
          {"reason", c.reason},
          {"wall_clock", c.wall_clock},
          {"seed_makes", c.seed_makes},
          {"margin", number(c.margin)},
          {"band", c.band},
          {"family", c.family},
          {"p_support", number(c.p_support)},
          {"p_refute", number(c.p_refute)},
          {"p_support_holm", number(c.p_support_holm)},
          {"p_refute_holm", number(c.p_refute_holm)},
          {"figures", figures_json(c)},
          {"held_out", held_out_json(c.held_out)}};
}

std::string experiment_json(const Plan& plan, const Findings& f, const std::vector<io::Json>& results) {
  OJson doc;
  doc["experiment"] = "self-contact";
  doc["command"] = command_line(plan.opt);
  doc["tecido"] = from(io::provenance_json());
  doc["scene"] = plan.opt.scene_path;
  doc["seed_table"] = plan.opt.seed_table_path;
  doc["simulated_time"] = plan.settings.simulated_time;
  doc["quick"] = plan.opt.quick;
  doc["seeds"] = plan.settings.seeds;
  OJson dets = OJson::array();
  for (ContactTest t : plan.detectors) dets.push_back(contact_test_name(t));
  doc["detectors"] = dets;
  doc["elasticity_as"] = plan.baseline.elasticity_as;
  doc["strength"] = plan.baseline.strength;
  doc["interpretation"] = from(interpretation_json(plan.baseline));
  doc["wind_model"] = {{"about", "constant magnitude, heading rate t + phase + b0 + W(t): b0 uniform, W a random walk "
                                 "(core/dynamics/random_wind.h)"},
                       {"knot_interval", plan.base.forces.wind->random->knot_interval},
                       {"seed_of_run", fmt::format("substream(scene seed, seed index); calibration: substream(scene seed, "
                                                   "{} + seed index)", kCalibrationStream)},
                       {"scene_seed", plan.base.seed}};
  doc["calibration"] = calibration_section(plan, f);
  OJson claims = OJson::array();
  for (const Claim& c : f.claims) {
    OJson j = claim_json(c);
    const std::string r = robustness_of(f, c.id);
    j["robustness"] = r.empty() ? OJson(nullptr) : OJson(r);
    claims.push_back(j);
  }
  doc["claims"] = claims;
  doc["cells"] = cells_json(plan, f);
  doc["sensitivity"] = sensitivity_section(plan, f);
  doc["timing"] = {{"tritri", from(f.tritri)}, {"phases", from(f.phases)}};
  doc["errors"] = f.errors;
  doc["runs"] = runs_json(plan, results);
  return doc.dump(2) + "\n";
}

}  // namespace tecido::suites::self_contact
