#include "comparisons/suites/ccd/ccd_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

namespace tecido::suites::ccd {

namespace {

/// The engine names of the results (the registry's order), from the first family that ran.
std::vector<std::string> engine_names(const std::vector<FamilyResult>& results, const std::vector<std::string>& failed) {
  for (std::size_t k = 0; k < results.size(); ++k)
    if (failed[k].empty()) {
      std::vector<std::string> names;
      for (const EngineTally& e : results[k].engines) names.push_back(e.engine);
      return names;
    }
  return {};
}

std::string header(const std::string& first, const std::vector<std::string>& engines) {
  std::string md = "| " + first + " |", rule = "|---|";
  for (const auto& e : engines) md += " " + e + " |", rule += "---:|";
  return md + "\n" + rule + "\n";
}

/// "fn / fp" (and "(n null)" when the engine could not answer some), "n/a" when it answered none.
std::string fn_fp_cell(const EngineTally& e) {
  const agreement::Tally& t = e.tally;
  if (t.no_answer == t.cases) return "n/a";
  std::string s = fmt::format("{} / {}", t.misses, t.false_hits);
  if (t.no_answer) s += fmt::format(" ({} null)", t.no_answer);
  return s;
}

std::string toi_cell(const EngineTally& e) {
  if (e.tally.both_hit == 0) return "–";
  std::string s = fmt::format("{:.2g} / {:.2g}", e.tally.max_t_error, e.mean_toi_error());
  // "late" counts tois certainly after t* (the referee's own, rounded up, among them); "up to" is
  // the largest toi - t* against the referee's toi, shown where it is positive.
  if (e.toi_after && e.max_toi_late > 0)
    s += fmt::format(" ({} late, up to +{:.2g})", e.toi_after, e.max_toi_late);
  else if (e.toi_after)
    s += fmt::format(" ({} late)", e.toi_after);
  return s;
}

/// Per engine: queries, seconds, false negatives and positives, contacts and non-contacts summed
/// over the families that ran.
struct Totals {
  long queries = 0, fn = 0, fp = 0, contacts = 0, non_contacts = 0, answered = 0;
  double seconds = 0.0;
  std::vector<std::string> fn_families;
};

std::map<std::string, Totals> totals(const std::vector<FamilyResult>& results, const std::vector<std::string>& failed) {
  std::map<std::string, Totals> t;
  for (std::size_t k = 0; k < results.size(); ++k) {
    if (!failed[k].empty()) continue;
    const FamilyResult& r = results[k];
    for (const EngineTally& e : r.engines) {
      Totals& x = t[e.engine];
      const agreement::Tally& c = e.tally;
      x.queries += c.cases, x.seconds += e.seconds, x.fn += c.misses, x.fp += c.false_hits;
      if (c.no_answer == c.cases) continue;
      x.answered += c.cases - c.no_answer, x.contacts += r.contacts, x.non_contacts += r.queries - r.contacts;
      if (c.misses) x.fn_families.push_back(fmt::format("{} ({})", r.family, c.misses));
    }
  }
  return t;
}

std::string join(const std::vector<std::string>& xs) {
  std::string s;
  for (std::size_t i = 0; i < xs.size(); ++i) s += (i ? ", " : "") + xs[i];
  return s;
}

}  // namespace

std::string method_markdown(const Settings& s, std::uint64_t seed) {
  std::string md = fmt::format(
      "Continuous collision (vertex-face, edge-edge; linear motion over t in [0, 1]): {} queries per constructed "
      "family and {} per random family (seed {}), every engine against the exact referee (`reference/exact_ccd.h`: exact on the doubles). Every family but "
      "`random` is built on small dyadic rationals with its answer known by construction (contact and its time), "
      "moved off the axes by exact dyadic affine maps and relabelled; the referee must reproduce every constructed "
      "answer, and on the first {} queries of each family it must give the same answer without its floating-point "
      "filter. FN = contacts an engine missed, FP = misses it called hits; time-of-impact error |toi - t*| where both "
      "hit (max / mean; \"late\": toi certainly after t*, which the referee's own toi is when t* is not a double and "
      "rounds up to the nearest one; \"up to\": the largest toi - t*). ns/query: wall time over the family's block, one thread of "
      "this run (cases share the machine; the benchmarks BM_CCD measure speed). Scale family: 2^e for e in {}, offsets "
      "2^k for k in {}; near misses by {} units of 2^-52.\n\nFamilies:\n\n",
      s.per_family, s.random_per_family, seed, s.unfiltered_per_family, fmt::join(s.scale_exponents, ", "),
      fmt::join(s.offset_exponents, ", "), fmt::join(s.near_miss_ulps, ", "));
  for (const Family& f : families()) md += fmt::format("- `{}`: {}\n", family_name(f), f.about);
  return md + "\n";
}

std::string outside_markdown(const std::vector<SuiteEngine>& engines) {
  std::string md;
  for (const SuiteEngine& e : engines) {
    if (!e.is_outside()) continue;
    std::string kinds;
    for (CcdKind k : {CcdKind::VertexFace, CcdKind::EdgeEdge})
      if (e.models(k)) kinds += std::string(kinds.empty() ? "" : " and ") + ccd_kind_name(k);
    md += fmt::format("- `{}`: {}; answers {}{}.\n", e.name, e.outside->door(), kinds,
                      e.outside->is_process() ? "; its ns/query includes the round trips of its door" : "");
  }
  if (md.empty()) return md;
  return "Outside engines (checked like the reference engines: on random motion only, false negative, false "
         "positive and unanswered shares within /ccd/outside_random_max_*_rate, and no toi later than the "
         "referee's first contact by more than /ccd/outside_random_max_toi_late; their adversarial rows are "
         "reported):\n\n" +
         md + "\n";
}

std::string kind_tables(CcdKind kind, const std::vector<FamilyResult>& results, const std::vector<std::string>& failed,
                        const std::vector<std::string>& not_modelled) {
  const auto off = [&](const std::string& e) {
    return std::find(not_modelled.begin(), not_modelled.end(), e) != not_modelled.end();
  };
  const std::vector<std::string> engines = engine_names(results, failed);
  std::string fnfp = header("family | queries | contacts", engines), toi = header("family", engines),
              ns = header("family", engines);
  fnfp.replace(fnfp.find("|---|"), 5, "|---|---:|---:|");
  const auto& fams = families();
  for (std::size_t k = 0; k < fams.size(); ++k) {
    if (fams[k].kind != kind) continue;
    if (!failed[k].empty()) {
      fnfp += fmt::format("| {} | failed: {} |\n", fams[k].name, failed[k]);
      continue;
    }
    const FamilyResult& r = results[k];
    fnfp += fmt::format("| {} | {} | {} |", fams[k].name, r.queries, r.contacts);
    toi += "| " + std::string(fams[k].name) + " |";
    ns += "| " + std::string(fams[k].name) + " |";
    for (const EngineTally& e : r.engines) {
      if (off(e.engine)) {
        fnfp += " not modelled |", toi += " – |", ns += " – |";
        continue;
      }
      fnfp += " " + fn_fp_cell(e) + " |";
      toi += " " + toi_cell(e) + " |";
      ns += e.tally.no_answer == e.tally.cases ? " n/a |" : fmt::format(" {:.0f} |", e.ns_per_query());
    }
    fnfp += "\n", toi += "\n", ns += "\n";
  }
  std::string refused;
  for (const auto& e : not_modelled) refused += fmt::format("{}: not modelled by {}.\n", ccd_kind_name(kind), e);
  return fmt::format("### {}\n\n{}False negatives / false positives against the referee:\n\n{}\nTime-of-impact "
                     "error where both hit, max / mean:\n\n{}\nns per query:\n\n{}\n",
                     ccd_kind_name(kind), refused.empty() ? "" : refused + "\n", fnfp, toi, ns);
}

std::string referee_table(const std::vector<FamilyResult>& results, const std::vector<std::string>& failed) {
  std::string md = "### The referee\n\n| family | constructed answers | referee differs | checked without filter | "
                   "differs |\n|---|---:|---:|---:|---:|\n";
  for (std::size_t k = 0; k < results.size(); ++k) {
    if (!failed[k].empty()) continue;
    const FamilyResult& r = results[k];
    md += fmt::format("| {} | {} | {} | {} | {} |\n", r.family, r.known, r.known_mismatch, r.unfiltered,
                      r.unfiltered_mismatch);
  }
  return md + "\n";
}

std::string conclusions(const std::vector<FamilyResult>& results, const std::vector<std::string>& failed) {
  const auto t = totals(results, failed);
  std::string md = "### From these tables\n\n";
  for (const auto& name : engine_names(results, failed)) {
    const Totals& x = t.at(name);
    md += fmt::format("- `{}`: ", name);
    md += x.fn_families.empty() ? "missed no contact" : "missed contacts on " + join(x.fn_families);
    md += fmt::format("; {} false positives in {} non-contacts ({:.3g}%)", x.fp, x.non_contacts,
                      x.non_contacts ? 100.0 * x.fp / x.non_contacts : 0.0);
    md += fmt::format("; {:.0f} ns per query over the whole mix", x.queries ? 1e9 * x.seconds / x.queries : 0.0);
    if (x.answered < x.queries) md += fmt::format(" (answers {} of {} queries)", x.answered, x.queries);
    md += ".\n";
  }
  if (t.count("core") && t.count("exact") && t.at("exact").seconds > 0)
    md += fmt::format("\nOver this mix core took {:.3g}x the referee's time per query", t.at("core").seconds / t.at("exact").seconds);
  if (t.count("core") && t.count("fcl") && t.at("fcl").seconds > 0)
    md += fmt::format(" and {:.3g}x FCL's", t.at("core").seconds / t.at("fcl").seconds);
  return md + ".\n\n";
}

std::string sheet_markdown(const SheetResult& r, const SheetSettings& s) {
  std::string md = fmt::format(
      "### A sheet through a sheet\n\nTwo {0}x{0} sheets in one mesh; one falls through the other within one step of "
      "{1} s (comparisons/suites/ccd/sheet_through_sheet.h).\n\n| measurement | value |\n|---|---:|\n"
      "| intersecting pairs in the two frames (core + exact) | {2} |\n| referee's contacts between the frames | {3} |\n"
      "| core (candidates confirmed exactly): contacts / missed / extra | {4} / {5} / {6} |\n"
      "| core's candidates vs core-brute's: pairs in only one | {7} |\n| core-brute: missed | {8} |\n"
      "| discrete + no response: checks seeing a pair / ended below the other sheet | {9} / {10} |\n"
      "| continuous + impulse: referee's contacts between consecutive frames over {11} of {12} steps | {13} |\n\n",
      s.n, s.dt, r.discrete_pairs, r.exact_contacts, r.core_contacts, r.core_missed, r.core_extra, r.candidates_differ,
      r.brute_missed, r.discrete_run_contacts, r.discrete_passed ? "yes" : "no", r.impulse_steps, s.steps,
      r.impulse_contacts);
  const bool invisible = r.discrete_pairs == 0 && r.discrete_run_contacts == 0 && r.discrete_passed;
  md += fmt::format("From this table: discrete detection {} the pass-through; continuous detection {} ({} contacts); "
                    "with the impulse response the sheets {}.\n\n",
                    invisible ? "never saw" : "saw part of", r.core_missed == 0 && r.core_extra == 0 ? "found exactly the referee's contacts" : "differed from the referee",
                    r.exact_contacts, r.impulse_contacts == 0 ? "never touched between frames" : "still touched between frames");
  return md;
}

io::Json results_json(const std::vector<FamilyResult>& results) {
  io::Json j = io::Json::object();
  for (const FamilyResult& r : results) {
    if (r.family.empty()) continue;
    io::Json e = io::Json::object();
    for (const EngineTally& t : r.engines)
      e[t.engine] = {{"fn", t.tally.misses},
                     {"fp", t.tally.false_hits},
                     {"no_answer", t.tally.no_answer},
                     {"fn_rate", r.fn_rate(t)},
                     {"fp_rate", r.fp_rate(t)},
                     {"max_toi_error", t.tally.max_t_error},
                     {"mean_toi_error", t.mean_toi_error()},
                     {"toi_after", t.toi_after},
                     {"max_toi_late", t.max_toi_late},
                     {"ns_per_query", t.ns_per_query()}};
    j[r.family] = {{"queries", r.queries}, {"contacts", r.contacts}, {"known", r.known},
                   {"known_mismatch", r.known_mismatch}, {"unfiltered_mismatch", r.unfiltered_mismatch}, {"engines", e}};
  }
  return j;
}

}  // namespace tecido::suites::ccd
