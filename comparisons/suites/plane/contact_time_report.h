#pragma once
/// The `plane` suite's report on contact time by bisection: the method (from the settings), the
/// table of every cell, conclusions derived from it, its data file and report.json data.
#include "comparisons/suites/plane/contact_time.h"

#include <string>

namespace tecido::suites::plane {

std::string contact_method(const ContactTimeSettings& s);
/// One row per integrator, step and level; a failed or incomplete cell shows its reason.
std::string contact_table(const ContactTimeSettings& s, const ContactTable& t);
/// Per integrator: for one exact for constant acceleration, its worst error as a multiple of the
/// tolerance; for the others, where the error stops as the tolerance shrinks; then the cost of a
/// level in bisections per contact. Read from `t`; incomplete cells are left out and named.
std::string contact_conclusions(const ContactTimeSettings& s, const ContactTable& t);
/// "integrator h tolerance max_error bisections_per_contact" per complete cell (contact_time.dat).
std::string contact_dat(const ContactTimeSettings& s, const ContactTable& t);
/// [{"integrator","h","level","tolerance","max_error","contacts","bisections_per_contact","ns_per_drop"
/// (,"error")}] in table order.
io::Json contact_json(const ContactTimeSettings& s, const ContactTable& t);

}  // namespace tecido::suites::plane
