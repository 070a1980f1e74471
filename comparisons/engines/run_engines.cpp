#include "comparisons/engines/run_engines.h"

#include "comparisons/engines/ccd_engines.h"
#include "comparisons/engines/dynamics_engines.h"
#include "comparisons/engines/segment_plane_engines.h"
#include "comparisons/engines/self_collision_engines.h"
#include "comparisons/engines/tri_tri_engines.h"
#include "core/dynamics/integrator.h"

#include <stdexcept>

namespace tecido {

namespace {

std::vector<std::string> outside_names(const outside::OutsideEngines* outside, bool outside::Capabilities::*cap) {
  std::vector<std::string> out;
  if (outside)
    for (const auto& e : outside->with(cap)) out.push_back(e->name());
  return out;
}

outside::OutsideEnginePtr outside_engine(const std::string& name, const outside::OutsideEngines* outside,
                                         bool outside::Capabilities::*cap) {
  auto e = outside ? outside->find(name) : nullptr;
  if (!e || !(e->capabilities().*cap)) throw std::invalid_argument("no engine \"" + name + "\" answers that question");
  return e;
}

}  // namespace

std::vector<std::string> tri_tri_engine_names(const outside::OutsideEngines* outside) {
  std::vector<std::string> names;
  for (const auto& e : tri_tri_engines()) names.push_back(e.name);
  for (auto& n : outside_names(outside, &outside::Capabilities::tri_tri)) names.push_back(std::move(n));
  return names;
}

std::vector<std::optional<bool>> tri_tri_answers(const std::string& name, const std::vector<outside::TriTriQuery>& queries,
                                                 const outside::OutsideEngines* outside) {
  if (const TriTriEngine* e = find_tri_tri_engine(name)) {
    std::vector<std::optional<bool>> out;
    out.reserve(queries.size());
    for (const auto& q : queries) out.push_back(e->test(q.a, q.b));
    return out;
  }
  return outside_engine(name, outside, &outside::Capabilities::tri_tri)->tri_tri(queries);
}

std::vector<std::string> segment_plane_engine_names(const outside::OutsideEngines* outside) {
  std::vector<std::string> names;
  for (const auto& e : segment_plane_engines()) names.push_back(e.name);
  for (auto& n : outside_names(outside, &outside::Capabilities::segment_plane)) names.push_back(std::move(n));
  return names;
}

std::vector<std::optional<SegmentPlaneHit>> segment_plane_answers(const std::string& name,
                                                                  const std::vector<outside::SegmentPlaneQuery>& queries,
                                                                  const outside::OutsideEngines* outside) {
  if (const SegmentPlaneEngine* e = find_segment_plane_engine(name)) {
    std::vector<std::optional<SegmentPlaneHit>> out;
    out.reserve(queries.size());
    for (const auto& q : queries) out.push_back(e->test(q.plane, q.from, q.to));
    return out;
  }
  return outside_engine(name, outside, &outside::Capabilities::segment_plane)->segment_plane(queries);
}

bool answers_ccd(const outside::OutsideEngine& engine) {
  const outside::Capabilities c = engine.capabilities();
  return c.ccd_vertex_face || c.ccd_edge_edge;
}

std::vector<std::optional<CcdAnswer>> ccd_answers(const std::string& name, const std::vector<CcdQuery>& queries,
                                                  const outside::OutsideEngines* outside) {
  if (const CcdEngine* e = find_ccd_engine(name)) {
    std::vector<std::optional<CcdAnswer>> out;
    out.reserve(queries.size());
    io::CcdQueryEntry entry;
    for (const auto& q : queries) {
      entry.query = q;
      out.push_back(answer_ccd_entry(*e, entry));
    }
    return out;
  }
  auto e = outside ? outside->find(name) : nullptr;
  if (!e || !answers_ccd(*e)) throw std::invalid_argument("no engine \"" + name + "\" answers that question");
  return e->ccd(queries);
}

std::vector<outside::OutsideEnginePtr> outside_ccd_engines(const outside::OutsideEngines* outside) {
  std::vector<outside::OutsideEnginePtr> out;
  if (outside)
    for (const auto& e : outside->all())
      if (answers_ccd(*e)) out.push_back(e);
  return out;
}

std::vector<std::string> ccd_engine_names(const outside::OutsideEngines* outside) {
  std::vector<std::string> names;
  for (const auto& e : ccd_engines()) names.push_back(e.name);
  for (const auto& e : outside_ccd_engines(outside)) names.push_back(e->name());
  return names;
}

std::vector<std::string> builtin_engine_names() {
  std::vector<std::string> names;
  for (const auto& e : tri_tri_engines()) names.push_back(e.name);
  for (const auto& e : segment_plane_engines()) names.push_back(e.name);
  for (const auto& e : self_collision_engines()) names.push_back(e.name);
  for (const auto& e : ccd_engines()) names.push_back(e.name);
  for (IntegratorKind k : engines::core_integrators()) names.push_back(integrator_name(k));
  names.push_back("exact");
  return names;
}

}  // namespace tecido
