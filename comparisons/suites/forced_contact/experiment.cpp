#include "comparisons/suites/forced_contact/experiment.h"

#include "comparisons/io/input_error.h"
#include "comparisons/suites/forced_contact/document.h"
#include "comparisons/suites/random.h"

#include <fmt/format.h>

namespace tecido::suites::forced_contact {

Plan make_plan(const Options& o) {
  if (o.seeds < 0) throw io::UsageError("--seeds must be >= 1");
  Plan p;
  p.opt = o;
  p.settings = settings(o.quick);
  if (o.seeds > 0) p.settings.seeds = o.seeds;
  for (int h = 0; h < static_cast<int>(p.settings.holds.size()); ++h)
    for (int r = 0; r < static_cast<int>(p.settings.responses.size()); ++r)
      for (int s = 0; s < p.settings.seeds; ++s) p.cases.push_back({h, r, s});
  return p;
}

io::Json case_id(const CaseSpec& c) { return {c.hold, c.response, c.seed}; }

Sweep make_sweep(const std::shared_ptr<const Plan>& plan) {
  Sweep s;
  s.cases = plan->cases.size();
  s.run_case = [plan](std::size_t k) {
    const CaseSpec& c = plan->cases[k];
    const Settings& st = plan->settings;
    io::Json j = run_json(run_forced(plan->scene, st, st.responses[c.response], st.holds[c.hold], c.seed));
    j["case"] = case_id(c);
    return j;
  };
  return s;
}

Findings find(const Plan& plan, const std::vector<io::Json>& results) {
  const Settings& st = plan.settings;
  Findings f;
  f.results.resize(results.size());
  f.runs.assign(st.holds.size(), std::vector<std::vector<const RunResult*>>(
                                      st.responses.size(), std::vector<const RunResult*>(st.seeds, nullptr)));
  for (std::size_t k = 0; k < results.size(); ++k) {
    const CaseSpec& c = plan.cases[k];
    if (const std::string* e = case_error(results[k])) {
      f.errors.push_back(fmt::format("case {} threw: {}", k, *e));
      continue;
    }
    f.results[k] = run_from_json(results[k]);
    f.runs[c.hold][c.response][c.seed] = &f.results[k];
  }
  for (std::size_t h = 0; h < st.holds.size(); ++h) {
    f.outcomes.emplace_back();
    for (std::size_t r = 0; r < st.responses.size(); ++r) {
      std::vector<const RunResult*> ok;
      for (const RunResult* run : f.runs[h][r])
        if (run) ok.push_back(run);
      const std::uint64_t boot = substream(plan.scene.seed, 1000000 + h * st.responses.size() + r);
      f.outcomes.back().push_back(cell_outcome(ok, st, boot));
    }
  }
  f.claims = forced_claims(f.runs, st);
  return f;
}

Outputs assemble(const Plan& plan, const std::vector<io::Json>& results) {
  const Findings f = find(plan, results);
  Outputs out;
  out.files.push_back({"experiment.json", experiment_json(plan, f, results)});
  out.files.push_back({"experiment.md", experiment_markdown(plan, f)});
  int counts[3] = {0, 0, 0};
  for (const Claim& c : f.claims) ++counts[static_cast<int>(c.verdict)];
  out.summary = fmt::format("claims: {} reproduced, {} not reproduced, {} inconclusive", counts[0], counts[1], counts[2]);
  return out;
}

std::string command_line(const Options& o) {
  std::string cmd = "tecido experiment forced-contact";
  if (o.quick) cmd += " --quick";
  if (o.seeds > 0) cmd += fmt::format(" --seeds {}", o.seeds);
  return cmd;
}

}  // namespace tecido::suites::forced_contact
