#include "comparisons/suites/plane/case_index.h"

#include <algorithm>
#include <stdexcept>

namespace tecido::suites::plane {

long category_cases(const Settings& s, const Category& category) {
  return category.random ? s.random_cases : s.cases_per_category;
}

std::vector<CaseRange> case_ranges(const Settings& s, const std::vector<Category>& categories) {
  return agreement::case_ranges(agreement::family_sizes(categories, s.random_cases, s.cases_per_category), s.block);
}

std::size_t Layout::size(CaseGroup g) const {
  switch (g) {
    case CaseGroup::Agreement: return blocks.size();
    case CaseGroup::ContactTime: return integrators * steps * levels;
    case CaseGroup::Drop: return heights;
  }
  return 0;
}

Layout layout(const Settings& s, const std::vector<Category>& categories, bool with_referee) {
  Layout l;
  if (with_referee) l.blocks = case_ranges(s, categories);
  l.integrators = s.contact_time.integrators.size();
  l.steps = s.contact_time.steps.size();
  l.levels = s.contact_time.levels.size();
  l.heights = s.drop.heights.size();
  return l;
}

namespace {
constexpr CaseGroup kOrder[] = {CaseGroup::Agreement, CaseGroup::ContactTime, CaseGroup::Drop};
}

std::size_t case_count(const Layout& l) {
  std::size_t n = 0;
  for (CaseGroup g : kOrder) n += l.size(g);
  return n;
}

CaseRef case_at(const Layout& l, std::size_t k) {
  for (CaseGroup g : kOrder) {
    if (k < l.size(g)) return {g, k};
    k -= l.size(g);
  }
  throw std::out_of_range("plane: case index past the last case");
}

std::size_t case_index(const Layout& l, CaseRef c) {
  std::size_t k = 0;
  for (CaseGroup g : kOrder) {
    if (g == c.group) return k + c.i;
    k += l.size(g);
  }
  return k;
}

ContactCell contact_cell(const Layout& l, std::size_t i) {
  return {i / (l.steps * l.levels), i / l.levels % l.steps, i % l.levels};
}

std::size_t contact_index(const Layout& l, ContactCell c) { return (c.integrator * l.steps + c.step) * l.levels + c.level; }

}  // namespace tecido::suites::plane
