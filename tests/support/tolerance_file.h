#pragma once
// Tolerance files for the tests that edit bands: data/tolerances.json with every number of some
// sections changed, and report.json reduced to what must not depend on the bands.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace tecido::testing {

/// Writes data/tolerances.json to `path` with every number of `sections` replaced by change(x)
/// (comment keys, "_...", are kept as they are). Returns how many numbers were changed.
inline int write_changed_tolerances(const std::filesystem::path& path, const std::vector<std::string>& sections,
                                    const std::function<double(double)>& change) {
  nlohmann::json doc = nlohmann::json::parse(slurp(std::filesystem::path(TECIDO_SOURCE_DIR) / "data" / "tolerances.json"));
  int changed = 0;
  for (const std::string& s : sections) {
    for (auto it = doc.at(s).begin(); it != doc.at(s).end(); ++it) {
      if (it.key().rfind('_', 0) == 0 || !it.value().is_number()) continue;
      it.value() = change(it.value().get<double>());
      ++changed;
    }
  }
  write_text(path, doc.dump(2));
  return changed;
}

/// The names of every check of every suite in a report.json, in order.
inline std::vector<std::string> check_names(const nlohmann::json& report) {
  std::vector<std::string> names;
  for (const auto& s : report.at("suites"))
    for (const auto& c : s.at("checks")) names.push_back(c.at("name").get<std::string>());
  return names;
}

/// Each suite's "data" without wall-clock entries ("seconds", "ns_per_...", "ms_per_..." keys at
/// any depth): what the suite measured apart from timings, so equal data means equal work.
inline nlohmann::json data_without_timings(const nlohmann::json& report) {
  std::function<nlohmann::json(const nlohmann::json&)> strip = [&](const nlohmann::json& j) -> nlohmann::json {
    if (j.is_object()) {
      nlohmann::json out = nlohmann::json::object();
      for (auto it = j.begin(); it != j.end(); ++it) {
        const std::string& k = it.key();
        if (k == "seconds" || k.rfind("ns_per", 0) == 0 || k.rfind("ms_per", 0) == 0) continue;
        out[k] = strip(it.value());
      }
      return out;
    }
    if (j.is_array()) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& v : j) out.push_back(strip(v));
      return out;
    }
    return j;
  };
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : report.at("suites")) out.push_back(strip(s.at("data")));
  return out;
}

}  // namespace tecido::testing
