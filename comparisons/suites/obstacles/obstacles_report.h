#pragma once
/// The `obstacles` suite's report: tables and prose as short functions of the run's values (no
/// measured number is a literal; every conclusion is derived from the table it summarises).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/obstacles/cases.h"
#include "comparisons/suites/obstacles/settings.h"

#include <string>
#include <vector>

namespace tecido::suites::obstacles {

/// The case results by case name (a case that threw holds {"error": ...}).
using Results = io::Json;

/// The result of case `name` when it ran and did not throw; nullptr otherwise.
const io::Json* completed_case(const Results& r, const std::string& name);

/// What runs, from the settings.
std::string method_markdown(const Settings& s);
/// The analytic cases against their closed forms.
std::string analytic_markdown(const Settings& s, const Results& r);
/// Fast particles and huge steps: step ends inside, tunnelling, guard corrections.
std::string fast_markdown(const Settings& s, const Results& r);
/// The seed's artefact table: springs through the block's interior per frame, both resolutions,
/// edge contacts off and on, then the matched comparison (placement, depth per spacing, share of
/// the springs across the edge) in words.
std::string block_markdown(const Settings& s, const Results& r);
/// Core beside Bullet's classic soft body (reference build), with what Bullet does not model.
std::string bullet_markdown(const Settings& s, const Results& r);

}  // namespace tecido::suites::obstacles
