// The block and Bullet parts of the `obstacles` report (declared in obstacles_report.h).
#include "comparisons/suites/obstacles/obstacles_report.h"

#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <algorithm>

namespace tecido::suites::obstacles {

namespace {

std::string cell(const io::Json* run, std::size_t f) {
  if (!run || f >= run->at("frames").size()) return "-";
  const io::Json& fr = run->at("frames")[f];
  return fmt::format("{} ({:.2g} mm)", fr[1].dump(), 1e3 * get_num(fr[2]));
}

std::string insets_text(const io::Json& run) {
  std::string out;
  for (const auto& f : run.at("insets")) out += fmt::format("{}{:.3g}", out.empty() ? "" : ", ", get_num(f));
  return out;
}

/// The matched comparison (check_plan.h, record_matched) in words, from the two edges-off runs.
std::string matched_prose(const Settings& s, const Results& r) {
  const io::Json* coarse = completed_case(r, block_name(s.block_sides[0], false));
  const io::Json* fine = completed_case(r, block_name(s.block_sides[1], false));
  if (!coarse || !fine) return "The matched comparison cannot be stated: a run is missing.\n";
  const int nc = s.block_sides[0] * s.block_sides[0], nf = s.block_sides[1] * s.block_sides[1];
  auto mm = [](const io::Json& run, const char* key) { return 1e3 * get_num(run.at(key)); };
  auto per_s = [](const io::Json& run, const char* key) { return get_num(run.at(key)) / get_num(run.at("spacing")); };
  const double dc = get_num(coarse->at("end_depth")), df = get_num(fine->at("end_depth"));
  return fmt::format(
      "Edges off (the seed's engine). Placement: the block's four top edges lie {} spacings in from the nearest "
      "particle column at {} particles (spacing {:.4g} mm) and {} at {} (spacing {:.4g} mm). At the run's end "
      "(t = {:.3g} s) the deepest spring of the {}-particle cloth is {:.3g} mm inside the block ({:.3g} spacings), of "
      "the {}-particle cloth {:.3g} mm ({:.3g} spacings): in metres the finer cloth sinks {} ({:.3g} times as deep); "
      "{} springs pass through the block at {} particles ({} springs crossed the top face's outline at t = 0; "
      "springs beside the block's corners cut it too), {} at {} ({} across). "
      "Deepest at any step (the landing included): {:.3g} mm ({:.3g} spacings) at {}, {:.3g} mm ({:.3g} spacings) at "
      "{}. The raw count (the table) grows with the edge's springs, about as n, and the share of all springs falls "
      "about as 1 / n: neither says anything by itself, so the checks compare depth per spacing and the share of the "
      "springs across the edge.\n",
      insets_text(*coarse), nc, mm(*coarse, "spacing"), insets_text(*fine), nf, mm(*fine, "spacing"),
      get_num(fine->at("end_time")), nc, 1e3 * dc, per_s(*coarse, "end_depth"), nf, 1e3 * df,
      per_s(*fine, "end_depth"), df < dc ? "less, as the seed's figures show" : "not less than the coarser one",
      df / dc, coarse->at("end_through").dump(), nc, coarse->at("across").dump(), fine->at("end_through").dump(), nf,
      fine->at("across").dump(), mm(*coarse, "max_spring_depth"), per_s(*coarse, "max_spring_depth"), nc,
      mm(*fine, "max_spring_depth"), per_s(*fine, "max_spring_depth"), nf);
}

}  // namespace

std::string block_markdown(const Settings& s, const Results& r) {
  std::vector<const io::Json*> runs;
  std::string head = "| t [s] |", rule = "|---|";
  for (int n : s.block_sides)
    for (bool on : {false, true}) {
      runs.push_back(completed_case(r, block_name(n, on)));
      head += fmt::format(" {} particles, edges {} |", n * n, on ? "on" : "off");
      rule += "---|";
    }
  std::string md = "### The seed's block (figs 10-13): springs through the block's interior per frame\n\n"
                   "Each cell: springs through the interior (deepest of them). " + head + "\n" + rule + "\n";
  std::size_t frames = 0;
  for (const io::Json* run : runs) frames = std::max(frames, run ? run->at("frames").size() : 0);
  for (std::size_t f = 0; f < frames; ++f) {
    double t = 0.0;
    for (const io::Json* run : runs)
      if (run && f < run->at("frames").size()) t = get_num(run->at("frames")[f][0]);
    md += fmt::format("| {:.3g} |", t);
    for (const io::Json* run : runs) md += " " + cell(run, f) + " |";
    md += "\n";
  }
  md += "| most at any step |";
  for (const io::Json* run : runs) md += run ? fmt::format(" {} |", run->at("max_through").dump()) : " - |";
  md += "\n| particle step ends inside |";
  for (const io::Json* run : runs) md += run ? fmt::format(" {} |", run->at("steps_inside").dump()) : " - |";
  return md + "\n\n" + matched_prose(s, r) + "\n";
}

std::string bullet_markdown(const Settings& s, const Results& r) {
  std::vector<std::string> names = {"bullet/sphere"};
  for (int n : s.block_sides) names.push_back(bullet_block_name(n));
  std::string md = "### Core beside Bullet's classic soft body\n\n| scene | engine | contact onset [s] | expected [s] | rest "
                   "height [mm] | deepest node inside [mm] | most springs through |\n|---|---|---|---|---|---|---|\n";
  std::vector<std::string> notes;
  for (const std::string& name : names) {
    const io::Json* d = completed_case(r, name);
    if (!d) {
      md += fmt::format("| {} | | {} | | | | |\n", name, r.contains(name) ? *case_error(r.at(name)) : "not run");
      continue;
    }
    for (const char* engine : {"core", "bullet"}) {
      const io::Json& e = d->at(engine);
      md += fmt::format("| {} | {} | {:.6g} | {:.6g} | {:.4g} | {:.4g} | {} |\n", name, engine, get_num(e.at("t_onset")),
                        get_num(d->at("t_onset_expected")), 1e3 * get_num(e.at("rest_height")),
                        1e3 * get_num(e.at("max_penetration")), e.at("max_through").dump());
    }
    for (const auto& n : d->at("not_modelled"))
      if (std::find(notes.begin(), notes.end(), n.get<std::string>()) == notes.end()) notes.push_back(n.get<std::string>());
  }
  md += "\nContact onset: core's first bisected contact; Bullet's first step end at which a node's velocity leaves "
        "free fall (its cloth falls flat and undragged until something touches it); expected: the analytic fall to the "
        "surface without drag. Core's deepest node is measured by the "
        "suite's own inside test; Bullet's nodes are pushed out softly and may sink, which the table measures.\n";
  md += "\nA second opinion on the contact time: FCL's continuous vertex-face test of every cloth vertex's path "
        "over each step of the free fall against the block as 12 triangles (FCL takes the path as straight; core "
        "bisects along its integrator's sub-steps).\n\n| scene | FCL [s] | core [s] | exact [s] | FCL - core [steps] "
        "|\n|---|---|---|---|---|\n";
  for (int n : s.block_sides) {
    const io::Json* f = completed_case(r, fcl_block_name(n));
    if (!f) {
      md += fmt::format("| {} | {} | | | |\n", fcl_block_name(n), r.contains(fcl_block_name(n)) ? "failed" : "not run");
      continue;
    }
    const double t_fcl = get_num(f->at("t_fcl")), t_core = get_num(f->at("t_core"));
    md += fmt::format("| {} | {:.9g} | {:.9g} | {:.9g} | {:.3g} |\n", fcl_block_name(n), t_fcl, t_core,
                      get_num(f->at("t_exact")), (t_fcl - t_core) / get_num(f->at("dt")));
  }
  md += "\nNot modelled by Bullet's classic soft body:\n\n";
  for (const std::string& n : notes) md += "- " + n + "\n";
  return md + "\n";
}

}  // namespace tecido::suites::obstacles
