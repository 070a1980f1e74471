#pragma once
/// The experiment's two plots, written under plan.opt.out_dir (data files always, SVG through
/// gnuplot when it is on PATH): experiment_cells.svg, every cell's mean share with its 95% interval
/// per counting detector beside the seed's value; experiment_effects.svg, the relative change of
/// each mode against no response with its 95% interval per detector beside the seed's (its
/// interval over its 18 cells). Returns the Markdown section that shows them.
#include "comparisons/suites/self_contact/findings.h"

#include <string>

namespace tecido::suites::self_contact {

std::string plots_section(const Plan& plan, const Findings& f);

}  // namespace tecido::suites::self_contact
