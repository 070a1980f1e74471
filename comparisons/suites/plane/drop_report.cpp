#include "comparisons/suites/plane/drop_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::plane {

std::string drop_method(const DropSettings& s, bool bullet) {
  std::string md = fmt::format(
      "\n### The same drops{}\n\nA particle dropped from rest at each height z0 onto the floor, restitution k = {:g}, "
      "dt = {:g} s, run until {:g} of the first rebound's flight after the analytic contact. Analytic contact time "
      "sqrt(2 z0 / g) and rebound apex k² z0. Core: bisected contact, midpoint; apex = the highest step end after "
      "the contact.",
      bullet ? " in Bullet" : "", s.elasticity, s.dt, s.into_fall);
  if (bullet)
    md += fmt::format(
        " Bullet rigid: a sphere of radius {:g} m (btSphereShape on btStaticPlaneShape; restitution sqrt(k) on each "
        "body, which Bullet multiplies), contact = the step whose impulse lifts it, heights of its lowest point. "
        "Bullet node: the deformable twin (one node), contact = first step end within its collision margin + {:g} m.",
        s.sphere_radius, s.node_slack);
  return md + "\n\n";
}

namespace {
std::string cell(double x, const char* f) { return std::isfinite(x) ? fmt::format(fmt::runtime(f), x) : "–"; }
}  // namespace

std::string drop_table(const DropTable& t, bool bullet) {
  std::string md = bullet ? "| z0 [m] | t analytic [s] | t core | t Bullet rigid | t Bullet node | apex analytic [m] | "
                            "apex core | apex Bullet rigid | apex Bullet node |\n"
                            "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
                          : "| z0 [m] | t analytic [s] | t core | apex analytic [m] | apex core |\n|---:|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const DropRow& r = t.rows[i];
    if (!t.error[i].empty()) {
      md += fmt::format("| {:g} | failed: {} |\n", r.z0, t.error[i]);
      continue;
    }
    md += fmt::format("| {:g} | {:.5f} | {} |", r.z0, r.t_exact, cell(r.t_core, "{:.5f}"));
    if (bullet) md += fmt::format(" {} | {} |", cell(r.t_rigid, "{:.5f}"), cell(r.t_node, "{:.5f}"));
    md += fmt::format(" {:.4f} | {} |", r.apex_exact, cell(r.apex_core, "{:.4f}"));
    if (bullet) md += fmt::format(" {} | {} |", cell(r.apex_rigid, "{:.4f}"), cell(r.apex_node, "{:.4f}"));
    md += "\n";
  }
  return md;
}

namespace {

/// The smallest and largest of f(row) over the rows that ran (NaN, NaN when there is none or one is NaN).
template <class F>
std::pair<double, double> range_of(const DropTable& t, F f) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (!t.error[i].empty()) continue;
    const double x = f(t.rows[i]);
    if (std::isnan(x)) return {NAN, NAN};
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  if (!(hi >= lo)) return {NAN, NAN};
  return {lo, hi};
}

std::string span(std::pair<double, double> r, const char* unit) {
  if (std::isnan(r.first)) return "missing for some height";
  return fmt::format("{:+.3g} to {:+.3g}{}", r.first, r.second, unit);
}

std::string node_words(const DropSettings& s, const DropTable& t) {
  const auto contact = range_of(t, [&](const DropRow& r) { return (r.t_node - r.t_exact) / s.dt; });
  const auto above = range_of(t, [](const DropRow& r) { return r.apex_node - r.node_margin; });
  const auto apex = range_of(t, [](const DropRow& r) { return r.apex_exact; });
  std::string md = fmt::format("- Bullet node: contact {} steps from the analytic time; ", span(contact, ""));
  if (std::isnan(above.second)) return md + "no rebound measured for some height.\n";
  md += above.second < 0.01 * apex.first
            ? fmt::format("it does not rebound: its highest point after the contact is at most {:.3g} m above its "
                          "margin, against an analytic apex of at least {:.3g} m.",
                          above.second, apex.first)
            : fmt::format("it rebounds up to {:.3g} m above its margin.", above.second);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (!t.error[i].empty() || t.rows[i].node_not_modelled.empty()) continue;
    md += " The twin lists as not modelled for this scene:\n";
    for (const std::string& n : t.rows[i].node_not_modelled) md += "  - " + n + "\n";
    return md;
  }
  return md + "\n";
}

}  // namespace

std::string drop_conclusions(const DropSettings& s, const DropTable& t) {
  std::string md = "\nFrom this table:\n\n";
  md += fmt::format("- Core: contact {} steps from the analytic time; apex {} relative to k² z0.\n",
                    span(range_of(t, [&](const DropRow& r) { return (r.t_core - r.t_exact) / s.dt; }), ""),
                    span(range_of(t, [](const DropRow& r) { return r.apex_core / r.apex_exact - 1.0; }), ""));
  bool bullet = false;
  for (std::size_t i = 0; i < t.rows.size(); ++i) bullet = bullet || (t.error[i].empty() && t.rows[i].bullet);
  if (!bullet) return md;
  md += fmt::format("- Bullet rigid sphere: contact {} steps from the analytic time (it is seen at a step end); apex {} "
                    "relative to k² z0.\n",
                    span(range_of(t, [&](const DropRow& r) { return (r.t_rigid - r.t_exact) / s.dt; }), ""),
                    span(range_of(t, [](const DropRow& r) { return r.apex_rigid / r.apex_exact - 1.0; }), ""));
  return md + node_words(s, t);
}

io::Json drop_data(const DropTable& t) {
  io::Json rows = io::Json::array();
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (!t.error[i].empty()) {
      rows.push_back({{"z0", t.rows[i].z0}, {"error", t.error[i]}});
      continue;
    }
    rows.push_back(drop_json(t.rows[i]));
  }
  return rows;
}

}  // namespace tecido::suites::plane
