// The suites' families as query sets (include/tecido/harness.h): the pairs and queries the tritri
// and ccd suites draw for the same seed, by the suites' own generators and substreams.
#include "comparisons/suites/ccd/families.h"
#include "comparisons/suites/tritri/families.h"
#include "comparisons/suites/tritri/settings.h"
#include "core/api/public_types.h"

#include <tecido/harness.h>

#include <algorithm>
#include <stdexcept>

namespace tecido::harness {

namespace {

/// Whether `name` is chosen by `options` (every family when none is named).
bool chosen(const CaseOptions& options, const std::string& name) {
  return options.families.empty() ||
         std::find(options.families.begin(), options.families.end(), name) != options.families.end();
}

/// std::invalid_argument for the first name of `options` that is not among `known`.
void check_family_names(const CaseOptions& options, const std::vector<std::string>& known, const char* suite) {
  for (const std::string& name : options.families)
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw std::invalid_argument(std::string("harness: no family \"") + name + "\" in the " + suite + " suite");
}

}  // namespace

std::vector<std::string> tri_tri_families() { return suites::agreement::family_names(suites::tritri::families()); }

std::vector<std::string> ccd_families() {
  std::vector<std::string> names;
  for (const auto& f : suites::ccd::families()) names.push_back(suites::ccd::family_name(f));
  return names;
}

std::vector<TriTriCase> tri_tri_cases(const CaseOptions& options) {
  check_family_names(options, tri_tri_families(), "tritri");
  const auto& families = suites::tritri::families();
  const suites::tritri::Settings s = suites::tritri::settings(options.quick);
  const std::uint64_t seed = suites::substream(options.seed, 2);  // as the suite's plan
  std::vector<TriTriCase> out;
  for (std::size_t f = 0; f < families.size(); ++f) {
    if (!chosen(options, families[f].name)) continue;
    const long count = families[f].random ? s.random_pairs : s.pairs_per_family;
    for (long k = 0; k < count; ++k) {
      io::TriPair p = suites::tritri::family_pair(seed, f, families[f], k);
      out.push_back(TriTriCase{std::move(p.id), families[f].name, p.a, p.b});
    }
  }
  return out;
}

std::vector<CcdCase> ccd_cases(const CaseOptions& options) {
  check_family_names(options, ccd_families(), "ccd");
  const auto& families = suites::ccd::families();
  const suites::ccd::Settings s = suites::ccd::settings(options.quick);
  std::vector<CcdCase> out;
  for (std::size_t f = 0; f < families.size(); ++f) {
    const std::string name = suites::ccd::family_name(families[f]);
    if (!chosen(options, name)) continue;
    const auto queries = suites::ccd::family_queries(f, s, options.seed);
    for (std::size_t k = 0; k < queries.size(); ++k)
      out.push_back(CcdCase{name + "/" + std::to_string(k), name, api::motion(queries[k].q)});
  }
  return out;
}

}  // namespace tecido::harness
