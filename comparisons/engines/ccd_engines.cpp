#include "comparisons/engines/ccd_engines.h"

#include "comparisons/io/input_error.h"
#include "core/geometry/ccd/ccd.h"
#include "reference/bullet_ccd.h"
#include "reference/exact_ccd.h"
#include "reference/fcl_adapter.h"

#include <stdexcept>

namespace tecido {

namespace {
std::optional<CcdAnswer> core_ccd(const CcdQuery& q) { return ccd(q); }
std::optional<CcdAnswer> exact(const CcdQuery& q) { return reference::to_ccd_answer(reference::exact_ccd(q)); }
std::optional<CcdAnswer> exact_rational(const reference::RationalCcdQuery& q) {
  return reference::to_ccd_answer(reference::exact_ccd(q));
}
std::optional<CcdAnswer> fcl(const CcdQuery& q) { return reference::fcl_ccd(q); }
std::optional<CcdAnswer> bullet(const CcdQuery& q) {
  if (q.kind != CcdKind::VertexFace) return std::nullopt;
  // bullet_ccd returns nullopt for edge-edge only: a vertex-face query is always answered.
  return reference::bullet_ccd(q);
}
}  // namespace

const std::vector<CcdEngine>& ccd_engines() {
  static const std::vector<CcdEngine> engines = {
      {"core", &core_ccd},
      {"exact", &exact, &exact_rational},
      {"fcl", &fcl},
      {"bullet", &bullet},  // vertex-face only (Bullet 3.24 has no edge-edge test)
  };
  return engines;
}

const CcdEngine* find_ccd_engine(const std::string& name) {
  for (const auto& e : ccd_engines())
    if (e.name == name) return &e;
  return nullptr;
}

bool prepare_ccd_entry(io::CcdQueryEntry& entry) {
  if (!entry.rational) return false;
  const reference::RationalCcdQuery& r = *entry.rational;
  entry.query = reference::nearest_double_query(r);
  for (const auto* frame : {&r.x0, &r.x1})
    for (const auto& point : *frame)
      for (const auto& c : point)
        if (!reference::is_exact_double(c)) return true;
  return false;
}

std::optional<CcdAnswer> answer_ccd_entry(const CcdEngine& engine, const io::CcdQueryEntry& entry) {
  if (entry.rational && engine.test_rational) return engine.test_rational(*entry.rational);
  try {
    return engine.test(entry.query);
  } catch (const std::domain_error&) {
    return std::nullopt;  // a rational beyond the doubles' range became infinite: no answer
  }
}

}  // namespace tecido
