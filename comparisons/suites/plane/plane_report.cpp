#include "comparisons/suites/plane/plane_report.h"

#include "comparisons/suites/agreement/report_text.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::plane {

namespace {
const char* band_words(TErrorBand b) {
  switch (b) {
    case TErrorBand::None: return "agreement only (the crossing fraction is ill-conditioned)";
    case TErrorBand::Near: return "agreement and max t error (`_t_error_near`)";
    case TErrorBand::Far: return "agreement and max t error (`_t_error_far`)";
  }
  return "";
}
}  // namespace

std::string method_markdown(const Settings& s, std::uint64_t seed, const std::string& referee,
                            const std::vector<Category>& categories) {
  std::string md = agreement::method_opening(
      {s.random_cases, s.cases_per_category, seed, s.block, "cases", "category"},
      fmt::format(": every engine's hit against the referee `{}` (CGAL/GMP rationals on the same doubles), and the "
                  "largest crossing-fraction error |t - t_exact| where both hit. ns/case: CPU time of the case's thread "
                  "per random case, while other cases run on the other cores. Categories:\n\n",
                  referee),
      categories);
  md += "\nChecked per group of categories, each group with its band in the tolerance file "
        "(/plane/<engine>_agreement_<group>): ";
  bool first = true;
  for (const CategoryGroup& g : category_groups()) {
    std::string members;
    for (const std::string& m : g.categories) members += (members.empty() ? "" : ", ") + m;
    md += fmt::format("{}`{}` ({}): {}", first ? "" : "; ", g.name, members, band_words(g.t_error));
    first = false;
  }
  return md + ". `core` decides exactly and is checked on every group; `core-seed`, the seed's floating-point test "
              "as written, and any other `core-*` engine are reported, not checked; any other engine is checked on "
              "every group at its own bands.\n\n";
}

namespace {
std::string t_cell(const Tally& t) { return t.both_hit > 0 ? fmt::format("{:.2e}", t.max_t_error) : "–"; }
}  // namespace

std::string agreement_table(const std::vector<Category>& categories, const AgreementTable& table) {
  std::string md = "Referee hits per category:";
  for (std::size_t c = 0; c < categories.size(); ++c)
    md += fmt::format("{} {} {}", c ? "," : "", categories[c].name,
                      table.error[c].empty() ? std::to_string(table.hits[c]) : std::string("failed"));
  md += ".\n\n| engine | category | cases | agree | false hits | misses | no answer | both hit | max t error | ns/case |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t e = 0; e < table.engines.size(); ++e) {
    for (std::size_t c = 0; c < categories.size(); ++c) {
      if (!table.error[c].empty()) {
        md += fmt::format("| {} | {} | failed | | | | | | | |\n", table.engines[e], categories[c].name);
        continue;
      }
      const Tally& t = table.tally[c][e];
      const std::string ns_cell = categories[c].random ? agreement::ns_text(table, e) : "";
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", table.engines[e], categories[c].name,
                        t.cases, t.agree, t.false_hits, t.misses, t.no_answer, t.both_hit, t_cell(t), ns_cell);
    }
  }
  return md + agreement::failed_notes(agreement::family_names(categories), table, "Category");
}

namespace {

const char* scope_words(CheckScope scope) {
  switch (scope) {
    case CheckScope::Exact: return "checked on every group";
    case CheckScope::Reference: return "checked on every group at its own bands";
    case CheckScope::Reported: return "reported, not checked";
  }
  return "";
}

/// "category (n of cases), ..." for the categories where `count` of the tally is positive.
std::string per_category(const std::vector<Category>& categories, const AgreementTable& table, std::size_t e,
                         agreement::Count count) {
  return agreement::family_counts(agreement::family_names(categories), table, e, count);
}

/// The largest t error where both hit, over the categories whose t error is checked, and over the
/// others (grazing: the fraction is ill-conditioned).
std::string t_error_words(const std::vector<Category>& categories, const AgreementTable& table, std::size_t e) {
  Tally checked, unchecked;
  std::string names;
  for (std::size_t c = 0; c < categories.size(); ++c) {
    if (!table.error[c].empty()) continue;
    const CategoryGroup* g = group_of(categories[c].name);
    if (g && g->t_error == TErrorBand::None) {
      unchecked.add(table.tally[c][e]);
      names += (names.empty() ? "" : ", ") + categories[c].name;
    } else {
      checked.add(table.tally[c][e]);
    }
  }
  std::string s = checked.both_hit > 0 ? fmt::format("largest |t - t_exact| where both hit {:.2e}", checked.max_t_error)
                                       : "no case where both hit";
  if (unchecked.both_hit > 0)
    s += fmt::format(" ({:.2e} on {}, where the fraction is ill-conditioned)", unchecked.max_t_error, names);
  return s;
}

std::string engine_findings(const std::vector<Category>& categories, const AgreementTable& table, std::size_t e,
                            CheckScope scope) {
  const std::string false_hits = per_category(categories, table, e, [](const Tally& t) { return t.false_hits; });
  const std::string misses = per_category(categories, table, e, [](const Tally& t) { return t.misses; });
  const std::string silent = per_category(categories, table, e, [](const Tally& t) { return t.no_answer; });
  std::string s = false_hits.empty() && misses.empty() ? "agrees with the referee on every evaluated case" : "";
  if (!false_hits.empty()) s += "false hits on " + false_hits;
  if (!misses.empty()) s += (s.empty() ? "" : "; ") + ("misses on " + misses);
  if (!silent.empty()) s += "; no answer on " + silent;
  s += "; " + t_error_words(categories, table, e);
  if (scope == CheckScope::Exact) {
    const std::string exact = per_category(categories, table, e, [](const Tally& t) { return t.exact_path; });
    s += exact.empty() ? "; its floating-point filter decided every case"
                       : "; its floating-point filter left cases to the exact path on " + exact;
  }
  return s;
}

}  // namespace

std::string agreement_conclusions(const std::vector<Category>& categories, const AgreementTable& table,
                                  const std::string& referee) {
  std::string md = "\nFrom this table:\n\n";
  for (std::size_t e = 0; e < table.engines.size(); ++e) {
    const CheckScope scope = check_scope(table.engines[e], referee);
    md += fmt::format("- `{}` ({}): {}.\n", table.engines[e], scope_words(scope), engine_findings(categories, table, e, scope));
  }
  return md;
}

std::string disagreements_markdown(std::size_t kept, long found, const std::string& file) {
  return agreement::disagreements_paragraph(kept, found, file, "category", "tecido plane --cases") + "\n";
}

io::Json agreement_json(const std::vector<Category>& categories, const AgreementTable& table) {
  io::Json data = io::Json::object();
  for (std::size_t e = 0; e < table.engines.size(); ++e) {
    io::Json& j = data[table.engines[e]];
    const double ns = agreement::ns_per_case(table, e);
    j["ns_per_case"] = std::isfinite(ns) ? io::Json(ns) : io::Json(nullptr);
    for (std::size_t c = 0; c < categories.size(); ++c) {
      const Tally& t = table.tally[c][e];
      io::Json& jc = j[categories[c].name];
      jc = {{"cases", t.cases},     {"agree", t.agree},       {"false_hits", t.false_hits}, {"misses", t.misses},
            {"null", t.no_answer},  {"both_hit", t.both_hit}, {"exact_path", t.exact_path}};
      jc["max_t_error"] = t.both_hit > 0 ? io::Json(t.max_t_error) : io::Json(nullptr);
      if (!table.error[c].empty()) jc["error"] = table.error[c];
    }
  }
  return data;
}

}  // namespace tecido::suites::plane
