#pragma once
/// The `drift` suite's comparisons of core with Bullet (reference build only), one function per
/// case group; each returns the case's result as JSON for the suite to check and report.
///  - twin: core's symplectic Euler against Bullet's deformable world in explicit mode on an
///    undamped cloth, step by step: round-off level first, then the chaotic motion amplifies it;
///  - falling: the same cloth falling flat onto a floor: the first contact time of each against
///    the analytic one, and the rest height;
///  - classic: the classic soft body's kLST calibrated to core's sag on a curtain, then both run at
///    another load the calibration never saw;
///  - wind: what neither Bullet engine models of a cloth in wind with drag (lists only).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/drift/settings.h"

namespace tecido::suites::drift {

/// {"unstable": {"step", "engine"} | null, "rms_window": max RMS distance over the first
/// twin_window seconds [m], "crossings": first times the RMS exceeds each of twin_thresholds [s]
/// ("nan": never), "curve": [[t, rms, max], ...] every step, "not_modelled": [...]}.
io::Json twin_case(const Settings& s);

/// {"unstable", "t_exact", "t_core" (the first bisected contact), "t_twin" (the first step end
/// with a node within Bullet's margin), "margin", "t_exact_margin" (the analytic time to fall to
/// the margin), "z_core" (max |z| at the end), "z_twin" (max z at the end)}; "nan" where a contact
/// never happened.
io::Json falling_case(const Settings& s);

/// {"calibration": {klst, core_sag, bullet_sag, relative_error, evaluations, sag_at_klst_1,
/// shape_rms, shape_max, bracketed}, "load": {factor, core_sag, bullet_sag, sag_ratio, shape_rms,
/// shape_max, bullet_shape_change}, "not_modelled": [...]}. Throws when an engine goes unstable
/// while settling (the suite then fails the group's checks with that reason).
io::Json classic_case(const Settings& s);

/// {"twin": [...], "classic": [...]}: the not-modelled lists of the wind scene.
io::Json wind_case(const Settings& s);

}  // namespace tecido::suites::drift
