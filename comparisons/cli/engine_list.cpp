#include "comparisons/cli/commands.h"
#include "comparisons/io/input_error.h"

#include <sstream>

namespace tecido::cli {

std::vector<std::string> parse_engine_list(const std::string& list, const std::vector<std::string>& known,
                                           const std::string& what) {
  std::vector<std::string> out;
  std::stringstream ss(list);
  std::string name;
  while (std::getline(ss, name, ',')) {
    if (name.empty()) continue;
    bool ok = false;
    for (const auto& k : known) ok = ok || k == name;
    if (!ok) {
      std::string all;
      for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
      throw io::UsageError("--engines: unknown " + what + " engine \"" + name + "\" (known: " + all + ")");
    }
    for (const auto& prev : out)
      if (prev == name) throw io::UsageError("--engines: \"" + name + "\" is named twice");
    out.push_back(name);
  }
  if (out.empty()) throw io::UsageError("--engines: no " + what + " engine given");
  return out;
}

}  // namespace tecido::cli
