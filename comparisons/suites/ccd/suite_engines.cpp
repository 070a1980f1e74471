#include "comparisons/suites/ccd/suite_engines.h"

#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/suites/thread_cpu_time.h"

#include <chrono>
#include <stdexcept>

namespace tecido::suites::ccd {

bool SuiteEngine::models(CcdKind kind) const {
  if (!outside) return true;
  const outside::Capabilities c = outside->capabilities();
  return kind == CcdKind::VertexFace ? c.ccd_vertex_face : c.ccd_edge_edge;
}

std::vector<SuiteEngine> suite_engines(const SuiteContext& ctx) {
  std::vector<SuiteEngine> out;
  for (const CcdEngine& e : ccd_engines())
    if (e.name == "exact" || ctx.selects(e.name)) out.push_back({e.name, &e, nullptr});
  if (!ctx.outside) return out;
  for (const outside::OutsideEnginePtr& e : ctx.outside->all()) {
    const outside::Capabilities c = e->capabilities();
    if ((c.ccd_vertex_face || c.ccd_edge_edge) && ctx.selects(e->name())) out.push_back({e->name(), nullptr, e});
  }
  return out;
}

std::vector<std::optional<CcdAnswer>> answer_block(const SuiteEngine& e, const std::vector<KnownQuery>& queries,
                                                   double& seconds) {
  std::vector<std::optional<CcdAnswer>> got(queries.size());
  if (e.builtin) {
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < queries.size(); ++i) got[i] = e.builtin->test(queries[i].q);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return got;
  }
  std::vector<CcdQuery> asked;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < queries.size(); ++i)
    if (e.models(queries[i].q.kind)) asked.push_back(queries[i].q), index.push_back(i);
  const double w0 = outside::door_seconds_on_this_thread(), c0 = thread_cpu_seconds();
  std::vector<std::optional<CcdAnswer>> answers;
  if (!asked.empty()) answers = e.outside->ccd(asked);
  seconds = thread_cpu_seconds() - c0 + (e.outside->is_process() ? outside::door_seconds_on_this_thread() - w0 : 0.0);
  if (answers.size() != asked.size()) throw std::runtime_error(e.name + " answered a different number of queries");
  for (std::size_t k = 0; k < index.size(); ++k) got[index[k]] = answers[k];
  return got;
}

}  // namespace tecido::suites::ccd
