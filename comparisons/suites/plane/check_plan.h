#pragma once
/// Which agreements the `plane` suite checks, declared before any case runs: names and bands depend
/// on the settings, the category table, the registered engines and the tolerance file's bands,
/// never on what the cases measure.
///
/// Agreement is checked per group of categories, each group with its own band in the tolerance
/// file: random; border (edge, corner: the crossing is on the border up to one rounding, so a
/// floating-point test decides by rounding); exact-geometry (parallel, in-plane, start-on, end-on:
/// built exactly on an axis-aligned plane); grazing (the crossing fraction is ill-conditioned, so
/// agreement only); far (offsets 1e3 .. 1e8 m).
#include "comparisons/suites/check.h"
#include "comparisons/suites/plane/categories.h"
#include "comparisons/suites/plane/settings.h"

#include <string>
#include <vector>

namespace tecido::suites::plane {

/// Which band the largest crossing-fraction error of a group is checked against, if any.
enum class TErrorBand { None, Near, Far };

struct CategoryGroup {
  std::string name;                     ///< as in the check names and the tolerance keys
  std::vector<std::string> categories;  ///< members, by category name
  TErrorBand t_error = TErrorBand::Near;
};

/// The groups, each category in exactly one: random, border, exact-geometry, grazing, far.
const std::vector<CategoryGroup>& category_groups();

/// The group `category` belongs to (nullptr for a category no group names).
const CategoryGroup* group_of(const std::string& category);

/// What is checked for one engine.
enum class CheckScope {
  Exact,      ///< `core`: decides exactly, so it must agree on every case of every group
  Reference,  ///< other engines (`fcl`, ...): every group, against their own bands /plane/<name>_...
  Reported,   ///< `core-seed` and any other `core-*` (the seed's tests as written), and the referee
};
CheckScope check_scope(const std::string& engine, const std::string& referee);

/// "plane/<engine>/agreement/<group>" and "plane/<engine>/t_error/<group>".
std::string agreement_check(const std::string& engine, const std::string& group);
std::string t_error_check(const std::string& engine, const std::string& group);
/// "plane/contact_time/<integrator>/h=<h>".
std::string contact_time_check(IntegratorKind k, double h);
constexpr const char* kCoreApexCheck = "plane/drop/core_apex_rel_error";
constexpr const char* kBulletContactCheck = "plane/drop/bullet_rigid_contact_time_error";

/// Every check, in this order:
///  - per checked engine and group: agreement (the share of cases whose hit equals the referee's,
///    at least /plane/<engine>_agreement_<group>, at most 1) and, unless the group is grazing, the
///    largest |t - t_exact| over cases where both hit (at most /plane/<engine>_t_error_near|far);
///    none without a referee (`referee` empty);
///  - per step h, for each integrator that is exact for constant acceleration (theory.h): the
///    largest contact-time error over the levels as a multiple of the bisection tolerance (at
///    most /plane/contact_time_over_tolerance);
///  - core's rebound apex, relative to k^2 z0 (at most /plane/drop_core_apex_rel), and, when
///    `with_bullet`, Bullet's rigid-sphere contact time error (at most
///    /plane/drop_bullet_contact_time_error_steps x the drop's step).
/// Throws io::InputError naming the tolerance file when a band is missing.
CheckList declare_checks(const Settings& s, const std::vector<std::string>& engines, const std::string& referee,
                         bool with_bullet, const Tolerances& tol);

}  // namespace tecido::suites::plane
