#pragma once
/// `tecido experiment forced-contact --frames`: the runs made viewable. Run 0 of every (response,
/// hold) is run again (deterministic: the very run of the ensemble) and its frames written every
/// Settings::sample seconds as Wavefront OBJ (io/frame_writer.h) into
/// DIR/frames/<response>-hold<H>/frame_<step>.obj, the grips' particles at their held positions.
#include "comparisons/suites/forced_contact/experiment.h"

#include <string>

namespace tecido::suites::forced_contact {

/// Writes the frames; returns how many were written.
long long write_frames(const Plan& plan, const std::string& dir);

}  // namespace tecido::suites::forced_contact
