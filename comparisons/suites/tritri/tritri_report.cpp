#include "comparisons/suites/tritri/tritri_report.h"

#include "comparisons/suites/agreement/report_text.h"
#include "comparisons/suites/tritri/check_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::tritri {

std::string method_markdown(const Settings& s, std::uint64_t seed, const std::string& referee,
                            const std::vector<Family>& families) {
  return agreement::method_opening(
      {s.random_pairs, s.pairs_per_family, seed, s.block, "pairs", "family"},
      fmt::format(". Each cell: pairs where the engine agrees with the referee `{}` (CGAL exact predicates) / pairs, "
                  "and the others apart: misses (the referee says the triangles intersect, the engine says no: cloth "
                  "passes through), false hits (the engine says they intersect, the referee no: cloth jitters) and "
                  "`n/a` (the engine gave no answer). ns/pair: CPU time of the case's thread per random pair, while "
                  "the other cases run on the other cores (the `bench` suite times the same tests alone). "
                  "Families:\n\n",
                  referee),
      families) + "\n";
}

std::string outside_markdown(const std::vector<outside::OutsideEnginePtr>& outside) {
  if (outside.empty()) return "";
  std::string names, processes;
  for (const auto& e : outside) {
    names += (names.empty() ? "`" : ", `") + e->name() + "`";
    if (e->is_process()) processes += (processes.empty() ? "`" : ", `") + e->name() + "`";
  }
  std::string md = "Outside engines " + names +
                   " (doors in the report's \"Outside engines\" table) answer each case's block in one batch through "
                   "their door and are checked on every family against `/tritri/outside_min_agreement`.";
  if (!processes.empty())
    md += " The ns/pair of the process engines " + processes +
          " is the case thread's CPU time (encoding the queries, decoding the answers) plus the wall time of their "
          "round trips (pipes and the other process's work; waiting for a turn at the process excluded): the cost of "
          "the door is part of it.";
  return md + "\n\n";
}

namespace {
/// "agree/pairs", then what the rest were where there is any: "(3 misses, 1 false hit, 2 n/a)".
std::string tritri_cell(const agreement::Tally& t) {
  std::string rest;
  const auto add = [&rest](long n, const char* one, const char* many) {
    if (n > 0) rest += fmt::format("{}{} {}", rest.empty() ? "" : ", ", n, n == 1 ? one : many);
  };
  add(t.misses, "miss", "misses");
  add(t.false_hits, "false hit", "false hits");
  add(t.no_answer, "n/a", "n/a");
  return fmt::format("{}/{}{}", t.agree, t.cases, rest.empty() ? "" : " (" + rest + ")");
}
}  // namespace

std::string agreement_table(const std::vector<Family>& families, const AgreementTable& table) {
  std::string md = "| engine | ns/pair |", rule = "|---|---:|", truth = "| (referee: intersecting) | |";
  for (std::size_t f = 0; f < families.size(); ++f) {
    md += " " + families[f].name + " |";
    rule += "---:|";
    truth += table.error[f].empty() ? fmt::format(" {} |", table.hits[f]) : " failed |";
  }
  md += "\n" + rule + "\n" + truth + "\n";
  for (std::size_t e = 0; e < table.engines.size(); ++e) {
    const std::string ns = agreement::ns_text(table, e);
    md += fmt::format("| {} | {} |", table.engines[e], ns.empty() ? "–" : ns);
    for (std::size_t f = 0; f < families.size(); ++f)
      md += " " + (table.error[f].empty() ? tritri_cell(table.tally[f][e]) : std::string("failed")) + " |";
    md += "\n";
  }
  return md + agreement::failed_notes(agreement::family_names(families), table, "Family");
}

namespace {
/// "agrees on every pair" or "misses on coplanar (3 of 500), ...; false hits on ...; no answer on ... (94)".
std::string engine_findings(const std::vector<Family>& families, const AgreementTable& table, std::size_t e) {
  const std::vector<std::string> names = agreement::family_names(families);
  const std::string misses = agreement::family_counts(names, table, e, [](const agreement::Tally& t) { return t.misses; });
  const std::string false_hits =
      agreement::family_counts(names, table, e, [](const agreement::Tally& t) { return t.false_hits; });
  const std::string silent =
      agreement::family_counts(names, table, e, [](const agreement::Tally& t) { return t.no_answer; }, false);
  std::string s = misses.empty() && false_hits.empty() ? "agrees with the referee on every evaluated pair" : "";
  if (!misses.empty()) s += "misses on " + misses;
  if (!false_hits.empty()) s += (s.empty() ? "" : "; ") + ("false hits on " + false_hits);
  if (!silent.empty()) s += "; no answer on " + silent;
  return s;
}

const char* scope_words(CheckScope scope) {
  switch (scope) {
    case CheckScope::EveryFamily: return "checked on every family";
    case CheckScope::RandomOnly: return "checked on random pairs; adversarial rows reported";
    case CheckScope::Reported: return "reported, not checked";
    case CheckScope::Outside: return "outside engine, checked on every family";
  }
  return "";
}

}  // namespace

std::string conclusions_markdown(const std::vector<Family>& families, const AgreementTable& table,
                                 const std::string& referee, const std::vector<std::string>& outside) {
  std::string md = "From this table:\n\n";
  for (std::size_t e = 0; e < table.engines.size(); ++e) {
    if (table.engines[e] == referee) continue;
    const bool is_outside = std::find(outside.begin(), outside.end(), table.engines[e]) != outside.end();
    md += fmt::format("- `{}` ({}): {}.\n", table.engines[e],
                      scope_words(check_scope(table.engines[e], referee, is_outside)), engine_findings(families, table, e));
  }
  return md;
}

std::string disagreements_markdown(std::size_t kept, long found, const std::string& file) {
  return agreement::disagreements_paragraph(kept, found, file, "family", "tecido tritri --pairs");
}

io::Json table_json(const std::vector<Family>& families, const AgreementTable& table) {
  io::Json data = io::Json::object();
  for (std::size_t e = 0; e < table.engines.size(); ++e) {
    const double ns = agreement::ns_per_case(table, e);
    io::Json& j = data[table.engines[e]];
    j["ns_per_pair"] = std::isfinite(ns) ? io::Json(ns) : io::Json(nullptr);
    for (std::size_t f = 0; f < families.size(); ++f) {
      const agreement::Tally& t = table.tally[f][e];
      j[families[f].name] = {{"agree", t.agree},         {"pairs", t.cases},           {"no_answer", t.no_answer},
                             {"misses", t.misses},       {"false_hits", t.false_hits}};
      if (!table.error[f].empty()) j[families[f].name]["error"] = table.error[f];
    }
  }
  return data;
}

}  // namespace tecido::suites::tritri
