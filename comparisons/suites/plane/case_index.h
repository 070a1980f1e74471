#pragma once
/// The `plane` suite's cases, indexed 0..case_count-1 in this order:
///   agreement     one block of one category: Settings::block cases (the last block of a category
///                 shorter), category by category in table order, blocks in case order; none
///                 without the exact referee;
///   contact time  integrator x step x level (the last fastest): every drop of one cell;
///   drop          one height of the drop group.
/// A case feeds the checks of one category group, one step or the drop group only, so a case that
/// throws takes down just those.
#include "comparisons/suites/agreement/case_blocks.h"
#include "comparisons/suites/plane/categories.h"
#include "comparisons/suites/plane/settings.h"

#include <cstddef>
#include <vector>

namespace tecido::suites::plane {

/// Cases [first, first + count) of one category (comparisons/suites/agreement/case_blocks.h; its
/// `family` is the index into the category table).
using agreement::CaseRange;

/// How many cases `category` has under `s`.
long category_cases(const Settings& s, const Category& category);

/// Every block, in index order. Together they cover each case of each category exactly once.
std::vector<CaseRange> case_ranges(const Settings& s, const std::vector<Category>& categories);

/// One cell of the contact-time table: indices into ContactTimeSettings's integrators, steps, levels.
struct ContactCell {
  std::size_t integrator = 0, step = 0, level = 0;
};

enum class CaseGroup { Agreement, ContactTime, Drop };

struct Layout {
  std::vector<CaseRange> blocks;
  std::size_t integrators = 0, steps = 0, levels = 0;  ///< the contact-time table's shape
  std::size_t heights = 0;                             ///< drops of the drop group
  std::size_t size(CaseGroup g) const;
};
/// The layout of `s`; no agreement blocks when `with_referee` is false.
Layout layout(const Settings& s, const std::vector<Category>& categories, bool with_referee);

/// A case: its group and its index inside the group.
struct CaseRef {
  CaseGroup group = CaseGroup::Agreement;
  std::size_t i = 0;
};
std::size_t case_count(const Layout& l);
/// The case at sweep index k (std::out_of_range past the end), and back.
CaseRef case_at(const Layout& l, std::size_t k);
std::size_t case_index(const Layout& l, CaseRef c);

/// Inside the contact-time group.
ContactCell contact_cell(const Layout& l, std::size_t i);
std::size_t contact_index(const Layout& l, ContactCell c);

}  // namespace tecido::suites::plane
