#include "comparisons/suites/selfcollision/check_plan.h"

#include <algorithm>

namespace tecido::suites::selfcollision {

std::string check_name(const std::string& engine, const std::string& source, const std::string& measure) {
  return "selfcollision/" + engine + "/" + source + "/" + measure;
}

CheckList declare_checks(const std::vector<FrameSource>& sources, const std::vector<std::string>& engines,
                         const std::string& truth, const Tolerances& tol, const std::vector<std::string>& outside) {
  CheckList checks;
  for (const std::string& e : engines) {
    if (e == truth) continue;
    const bool is_outside = std::find(outside.begin(), outside.end(), e) != outside.end();
    const Band band = tol.at_least(is_outside ? "/selfcollision/outside_min" : "/selfcollision/" + e + "_min", 1.0);
    for (const FrameSource& s : sources) {
      checks.declare(check_name(e, s.name, "precision"), band, "reported pairs that are true / reported, vs " + truth);
      checks.declare(check_name(e, s.name, "recall"), band, "true pairs reported / true pairs, vs " + truth);
    }
  }
  return checks;
}

namespace {
void fail_if_declared(CheckList& checks, const std::string& name, const std::string& reason) {
  if (checks.declared(name)) checks.fail(name, reason);
}
}  // namespace

void record_checks(CheckList& checks, const std::string& source, const std::vector<std::string>& engines,
                   const SourceScore& score) {
  if (!score.error.empty()) {
    for (const std::string& e : engines) {
      fail_if_declared(checks, check_name(e, source, "precision"), score.error);
      fail_if_declared(checks, check_name(e, source, "recall"), score.error);
    }
    return;
  }
  for (const EngineScore& e : score.engines) {
    const std::string p = check_name(e.engine, source, "precision"), r = check_name(e.engine, source, "recall");
    if (!checks.declared(p)) continue;  // the truth engine
    if (e.answered < score.frames) {
      const std::string why = std::to_string(score.frames - e.answered) + " of " + std::to_string(score.frames) +
                              " frames unanswered";
      fail_if_declared(checks, p, why);
      fail_if_declared(checks, r, why);
      continue;
    }
    checks.set(p, e.pairs.precision());
    if (score.true_pairs == 0) {
      checks.fail(r, "no true pair in the frames: recall is vacuous");
    } else {
      checks.set(r, e.pairs.recall());
    }
  }
}

}  // namespace tecido::suites::selfcollision
