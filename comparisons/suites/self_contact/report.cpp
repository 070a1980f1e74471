#include "comparisons/suites/self_contact/report.h"

#include "comparisons/suites/self_contact/plots.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

namespace tecido::suites::self_contact {

namespace {

std::string num(double x, const char* spec = "{:.4f}") { return std::isfinite(x) ? fmt::format(spec, x) : "n/a"; }

/// A value in the claim's unit: relative changes as percentages, the rest plain.
std::string in_unit(const Claim& c, double x) {
  if (!std::isfinite(x)) return "n/a";
  if (c.unit == "relative change" || c.unit == "difference of relative changes") return fmt::format("{:+.1f}%", 100.0 * x);
  if (c.unit == "ratio") return fmt::format("{:.2f}", x);
  return fmt::format("{:.3f}", x);
}

std::string p_value(double p) { return std::isfinite(p) ? fmt::format("{:.3g}", p) : "n/a"; }

std::string held_out_cell(const Claim& c) {
  const HeldOut& h = c.held_out;
  if (!h.computed) return "";
  const std::string same = h.verdict == c.verdict ? "same verdict" : "**verdict differs**";
  return fmt::format("{} [{}, {}], n {}: {}{} ({})", in_unit(c, h.observed), in_unit(c, h.ci95.lo), in_unit(c, h.ci95.hi),
                     h.n, verdict_name(h.verdict), h.reason.empty() ? "" : " (" + h.reason + ")", same);
}

std::string claim_row(const Claim& c) {
  const std::string ours = fmt::format("**{}** [{}, {}]", in_unit(c, c.observed), in_unit(c, c.ci95.lo), in_unit(c, c.ci95.hi));
  const std::string why = c.reason.empty() ? "" : " (" + c.reason + ")";
  return fmt::format("| `{}`{} | {} | {} | {}<br>{} | {} | {} / {} | **{}**{} | {} |\n", c.id, c.wall_clock ? " (wall-clock)" : "",
                     c.statement, c.seed_text, ours, c.observed_text, c.band, p_value(c.p_support_holm),
                     p_value(c.p_refute_holm), verdict_name(c.verdict), why, held_out_cell(c));
}

const char* const kClaimHead =
    "| claim | the seed says | the seed's value | ours, 95% interval | margin | Holm p: support / refute | verdict | "
    "without the calibration's cells |\n|---|---|---|---|---|---|---|---|\n";

std::string claims_table(const Findings& f, const std::string& detector, bool seed_makes) {
  std::string md = kClaimHead;
  for (const Claim& c : f.claims)
    if (c.detector == detector && c.seed_makes == seed_makes) md += claim_row(c);
  return md + "\n";
}

std::string claims_section(const Plan& plan, const Findings& f) {
  std::string md = "## The seed's claims\n\nEach claim is two tests (support, refute) with Holm's adjustment within its "
                   "family (a detector's ten claims; the premise's two; the cost's three); margins were set before any run "
                   "was compared. The last column recomputes a claim without the cell pairs that touch a calibration cell "
                   "(the fitted no-response cells are denominators of 6 of the 18 pairs of every mode claim).\n\n";
  for (ContactTest t : plan.detectors) {
    const std::string name = contact_test_name(t);
    md += fmt::format("### Frames counted with `{}`{}\n\n", name,
                      t == ContactTest::CoreMt ? " (the seed's detector: the faithful replication)"
                      : t == ContactTest::Core ? " (the exact detector: the corrected replication)" : "");
    md += claims_table(f, name, true);
    md += "Checks of ours (the seed never makes these claims):\n\n" + claims_table(f, name, false);
  }
  md += "### Claims that do not depend on the counting detector\n\n" + claims_table(f, "", true);
  return md + "Wall-clock claims are decided from timings of this run on this machine.\n\n";
}

std::string id_list(const Findings& f, const std::string& detector, Verdict v) {
  std::string out;
  for (const Claim& c : f.claims)
    if (c.detector == detector && c.verdict == v) out += (out.empty() ? "" : ", ") + ("`" + c.id + "`");
  return out.empty() ? "none" : out;
}

std::string reproduces_section(const Plan& plan, const Findings& f) {
  std::string md = "## What reproduces, under which reading\n\n";
  md += fmt::format("Reading: {}; {} wind seeds per cell; {} s per run.\n\n", describe(plan.baseline), plan.settings.seeds,
                    plan.settings.simulated_time);
  std::vector<std::string> dets;
  for (ContactTest t : plan.detectors) dets.push_back(contact_test_name(t));
  dets.push_back("");
  for (const std::string& d : dets) {
    md += fmt::format("- {}: reproduced: {}; not reproduced: {}; inconclusive: {}.\n",
                      d.empty() ? "Independent of the detector" : "Counted with `" + d + "`", id_list(f, d, Verdict::Reproduced),
                      id_list(f, d, Verdict::NotReproduced), id_list(f, d, Verdict::Inconclusive));
  }
  if (!f.robustness.empty()) {
    std::map<std::string, std::string> by;
    for (const Robustness& r : f.robustness) by[r.status] += (by[r.status].empty() ? "" : ", ") + ("`" + r.id + "`");
    md += fmt::format("- Across the sensitivity readings and detectors: robust: {}; fragile (the verdict flips inside the "
                      "plausible range): {}; unsettled: {}.\n",
                      by.count("robust") ? by["robust"] : "none", by.count("fragile") ? by["fragile"] : "none",
                      by.count("unsettled") ? by["unsettled"] : "none");
  }
  return md + "\n";
}

std::string rules_section(const Findings& f) {
  std::string md = "## Rules\n\n";
  std::map<std::string, bool> done;
  for (const Claim& c : f.claims) {
    if (done[c.id]) continue;
    done[c.id] = true;
    md += fmt::format("- `{}` ({}{}): {}\n", c.id, c.unit, c.wall_clock ? ", wall-clock" : "", c.rule);
  }
  return md + "\n";
}

std::string agreement_line(const char* what, const Agreement& a) {
  return fmt::format("| {} | {} | {} | {} | {} | {} |\n", what, a.cells, a.inside_pi95, num(a.mean_abs_diff),
                     num(a.rms_diff), num(a.correlation, "{:.2f}"));
}

std::string calibration_section(const Plan& plan, const Findings& f) {
  const auto cells = baseline_cells(plan, f, 0);
  int fit_cells = 0;
  for (bool b : plan.calibration.fit) fit_cells += b;
  std::string md = fmt::format(
      "## Calibration (declared)\n\nAir drag {} kg/s and swirl rate {} rad/s come from `{}`, fitted on {} cells (no "
      "response at one step; see the record's command and grid) with wind seeds the experiment does not use. Every other "
      "cell is a prediction. Agreement with the seed's values, counted with `{}`:\n\n",
      plan.calibration.air_drag, plan.calibration.swirl_rate, plan.calibration.file, fit_cells,
      contact_test_name(plan.detectors[0]));
  md += "| cells | count | seed value inside our 95% prediction interval | mean abs. difference | rms difference | "
        "correlation |\n|---|---:|---:|---:|---:|---:|\n";
  md += agreement_line("fitted", agreement(cells, plan.calibration.fit, true));
  md += agreement_line("predicted", agreement(cells, plan.calibration.fit, false));
  return md + "\n";
}

std::string sensitivity_section(const Plan& plan, const Findings& f) {
  if (f.rows.empty()) return "## Sensitivity\n\nNot run (--quick, --calibrate or --no-sensitivity).\n\n";
  std::string md = "## Sensitivity\n\nEach reading changes one open choice of the baseline; R reproduced, N not reproduced, "
                   "? inconclusive.\n\n| reading | choice | detector |";
  std::string sep = "|---|---|---|";
  for (const Robustness& r : f.robustness) md += " `" + r.id + "` |", sep += ":-:|";
  md += "\n" + sep + "\n";
  for (const SensitivityRow& row : f.rows) {
    std::string about;
    for (const Variant& v : plan.variants)
      if (v.id == row.variant) about = v.choice + ": " + v.about;
    md += fmt::format("| {} | {} | {} |", row.variant, about, row.detector);
    for (const Robustness& r : f.robustness) {
      std::string cell = " |";
      for (const Claim& c : row.claims)
        if (c.id == r.id) cell = c.verdict == Verdict::Reproduced ? " R |" : c.verdict == Verdict::NotReproduced ? " N |" : " ? |";
      md += cell;
    }
    md += "\n";
  }
  md += "| **status** | | |";
  for (const Robustness& r : f.robustness) md += " " + r.status + " |";
  return md + "\n\n";
}

std::string cells_section(const Plan& plan, const Findings& f) {
  const auto cells = baseline_cells(plan, f, 0);
  std::string md = fmt::format(
      "## The 72 cells\n\nCounted with `{}`: our mean share over the seeds ± the half-width of its 95% interval, then the "
      "seed's value; † marks a seed value outside our 95% prediction interval of one run, * a cell the calibration was "
      "fitted on.\n\n", contact_test_name(plan.detectors[0]));
  for (int w = 0; w < CellGrid::kWinds; ++w) {
    md += fmt::format("### Wind {} N\n\n| steps per second | elasticity | none | mode 1 | mode 2 | mode 3 |\n|---|---|---|---|---|---|\n",
                      CellGrid::winds[w]);
    for (int st = 0; st < CellGrid::kSteps; ++st)
      for (int e = 0; e < CellGrid::kElasticities; ++e) {
        const Cell first = CellGrid::cell(CellGrid::index({w, st, e, 0}));
        md += fmt::format("| {} | {} |", first.steps_per_second(), first.elasticity);
        for (int m = 0; m < CellGrid::kModes; ++m) {
          const CellStats& c = cells[CellGrid::index({w, st, e, m})];
          const bool out = std::isfinite(c.seed_value) && std::isfinite(c.s.pi95.lo) && !c.s.pi95.contains(c.seed_value);
          md += fmt::format(" {} ± {} / {}{}{} |", num(c.s.mean), num(0.5 * (c.s.ci95.hi - c.s.ci95.lo)), num(c.seed_value, "{:.5g}"),
                            out ? " †" : "", plan.calibration.fit[c.cell] ? " *" : "");
        }
        md += "\n";
      }
    md += "\n";
  }
  return md;
}

std::string runs_line(const Findings& f) {
  const Ensemble& e = f.ensembles[0];
  return fmt::format("{} runs in the baseline reading; {} went unstable (left out of the statistics); {} case(s) threw{}\n\n",
                     e.runs, e.unstable, f.errors.size(), f.errors.empty() ? "." : ":");
}

std::string errors_list(const Findings& f) {
  std::string md;
  for (const std::string& e : f.errors) md += "- " + e + "\n";
  return md.empty() ? md : md + "\n";
}

std::string method_section(const Plan& plan) {
  return fmt::format(
      "## Method\n\nThe wind: constant magnitude on every free particle (the cell's 0.09, 0.1 or 0.11 N), its heading "
      "turning about the vertical at the swirl rate plus a random offset: a uniform starting heading and a random walk of "
      "diffusion {} rad^2/s sampled every {} s (core/dynamics/random_wind.h; the seed's fig. 15 wind \"behaves randomly\", "
      "fig. 21's \"circles constantly\"). Seed index s gives every cell the same wind realisation, so differences between "
      "cells are paired. A run's share is its frames with a detected self-contact over its frames (one frame per step). "
      "Cell intervals: Student t over the seeds; effects: per seed, then Student t over the seeds; the seed's own spread: "
      "over its cells. Claim rules: see Rules.\n",
      plan.baseline.heading_diffusion, plan.base.forces.wind->random->knot_interval);
}

}  // namespace

std::string verdict_summary(const Findings& f) {
  int r = 0, n = 0, i = 0;
  for (const Claim& c : f.claims) {
    r += c.verdict == Verdict::Reproduced;
    n += c.verdict == Verdict::NotReproduced;
    i += c.verdict == Verdict::Inconclusive;
  }
  return fmt::format("claims: {} reproduced, {} not reproduced, {} inconclusive", r, n, i);
}

std::string experiment_markdown(const Plan& plan, const Findings& f) {
  std::string md = "# Self-contact experiment (the seed, section 3.1.3: fig. 21, tables 1-3)\n\n";
  md += fmt::format("`{}`{}. ", command_line(plan.opt), plan.opt.quick ? " (**--quick**: not comparable with the seed's 10 s)" : "");
  md += runs_line(f) + errors_list(f);
  md += claims_section(plan, f) + reproduces_section(plan, f) + rules_section(f) + calibration_section(plan, f);
  md += sensitivity_section(plan, f) + cells_section(plan, f) + plots_section(plan, f) + method_section(plan);
  return md;
}

}  // namespace tecido::suites::self_contact
