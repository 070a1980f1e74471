#include "comparisons/suites/agreement/report_text.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::agreement {

std::string sample_sentence(const Sample& s) {
  return fmt::format("{} random {} and {} {} of each adversarial {} (seed {}), in sweep cases of at most {} {} of one {}",
                     s.random, s.unit, s.per_family, s.unit, s.group, s.seed, s.block, s.unit, s.group);
}

std::string family_counts(const std::vector<std::string>& names, const AgreementTable& table, std::size_t e, Count count,
                          bool of_cases) {
  std::string s;
  for (std::size_t f = 0; f < names.size(); ++f) {
    if (!table.error[f].empty()) continue;
    const Tally& t = table.tally[f][e];
    const long n = count(t);
    if (n <= 0) continue;
    s += of_cases ? fmt::format("{}{} ({} of {})", s.empty() ? "" : ", ", names[f], n, t.cases)
                  : fmt::format("{}{} ({})", s.empty() ? "" : ", ", names[f], n);
  }
  return s;
}

std::string failed_notes(const std::vector<std::string>& names, const AgreementTable& table, const std::string& word) {
  std::string md;
  for (std::size_t f = 0; f < names.size(); ++f)
    if (!table.error[f].empty()) md += fmt::format("\n{} `{}` failed: {}\n", word, names[f], table.error[f]);
  return md;
}

std::string ns_text(const AgreementTable& table, std::size_t e) {
  const double ns = ns_per_case(table, e);
  return std::isfinite(ns) ? fmt::format("{:.0f}", ns) : "";
}

std::string disagreements_paragraph(std::size_t kept, long found, const std::string& file, const std::string& unit,
                                    const std::string& command) {
  return fmt::format(
      "\n{} of the {} disagreements with the referee are in `{}` (ids `engine:{}/k`); `{} DIR/{} --json`, DIR being "
      "this report's directory, reruns them with every engine.\n",
      kept, found, file, unit, command, file);
}

}  // namespace tecido::suites::agreement
