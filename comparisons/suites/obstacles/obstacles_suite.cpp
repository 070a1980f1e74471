#include "comparisons/suites/obstacles/obstacles_suite.h"

#include "comparisons/suites/obstacles/cases.h"
#include "comparisons/suites/obstacles/check_plan.h"
#include "comparisons/suites/obstacles/obstacles_report.h"
#include "comparisons/suites/obstacles/settings.h"
#include "comparisons/view/view_page.h"

#include <memory>

namespace tecido::suites {

namespace {

struct Plan {
  obstacles::Settings settings;
  std::vector<obstacles::Case> cases;
  CheckList checks;  ///< declared from the settings and the tolerance file, before any case runs
  std::string out_dir;  ///< the block runs' pages go to out_dir/obstacles
};

/// Writes the page of every case result holding a "view" (the block runs: block_case.h) as
/// OUT/obstacles/<name with '/' as '-'>.html and takes the view out of the result. Returns the
/// links and the report's paragraph.
std::string write_run_pages(const std::string& out_dir, io::Json& by_name, std::vector<PageLink>& views) {
  std::string pages;
  for (auto& [name, result] : by_name.items()) {
    if (!result.is_object() || !result.contains("view")) continue;
    std::string file = name;
    for (char& c : file)
      if (c == '/') c = '-';
    const std::string page = view::write_view_page(out_dir + "/obstacles", file, "obstacles " + name, result["view"]);
    result.erase("view");
    views.push_back({name + ": the run's frames in 3-D (springs through the block in orange)", "obstacles/" + page});
    pages += (pages.empty() ? "" : ", ") + ("`obstacles/" + page + "`");
  }
  if (pages.empty()) return "";
  return "The block runs' frames (the start and every counted frame) open in 3-D, the springs through the block in "
         "orange: " + pages + ".\n\n";
}

SuiteResult assemble(const Plan& plan, const std::vector<io::Json>& results) {
  CheckList checks = plan.checks;
  io::Json by_name = io::Json::object();
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    obstacles::record(checks, plan.settings, plan.cases[k], results.at(k));
    by_name[plan.cases[k].name] = results.at(k);
  }
  SuiteResult res;
  const std::string pages = write_run_pages(plan.out_dir, by_name, res.views);
  obstacles::record_matched(checks, plan.settings, by_name);
  res.name = "obstacles";
  const obstacles::Settings& s = plan.settings;
  res.markdown = obstacles::method_markdown(s) + obstacles::analytic_markdown(s, by_name) +
                 obstacles::fast_markdown(s, by_name) + obstacles::block_markdown(s, by_name) + pages +
                 obstacles::bullet_markdown(s, by_name);
  res.data = by_name;
  res.checks = checks.finish();
  return res;
}

}  // namespace

Sweep obstacles_sweep(const SuiteContext& ctx) {
  const obstacles::Settings s = obstacles::settings(ctx.quick);
  auto plan = std::make_shared<const Plan>(Plan{s, obstacles::cases(s, ctx.data_dir), obstacles::declare_checks(s, *ctx.tolerances, true), ctx.out_dir});
  Sweep sw;
  sw.cases = plan->cases.size();
  sw.run_case = [plan](std::size_t k) { return plan->cases.at(k).run(); };
  sw.assemble = [plan](const std::vector<io::Json>& results) { return assemble(*plan, results); };
  return sw;
}

SuiteResult run_obstacles_suite(const SuiteContext& ctx) { return run_sweep(&obstacles_sweep, ctx, "obstacles"); }

}  // namespace tecido::suites
