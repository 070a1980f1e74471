#pragma once
/// How the seed's claims move with the choices the seed leaves open. Each variant changes one
/// choice of the baseline reading (interpretation.h) to a documented alternative inside what the
/// seed's text allows; with the counting detectors (core-mt, core, core-rotation: the seventh
/// choice) every (variant, detector) is a row of verdicts. A claim is
///   robust     when every row gives it the same verdict,
///   fragile    when some row reproduces it and another does not (its verdict flips inside the
///              plausible range),
///   unsettled  otherwise (one decided verdict, inconclusive elsewhere).
#include "comparisons/suites/self_contact/claims.h"
#include "comparisons/suites/self_contact/interpretation.h"
#include "core/cloth/cloth_grid.h"

#include <string>
#include <vector>

namespace tecido::suites::self_contact {

struct Variant {
  std::string id;      ///< "baseline", "elasticity-restitution", ...
  std::string choice;  ///< the open choice it varies: "elasticity", "wind", "push strength", ...
  std::string about;   ///< the alternative in words
  Interpretation in;
  /// Its no-response cells are the baseline's runs, not run again: it changes only the edge
  /// modes' push, which acts in mode cells alone (a no-response run never reads it).
  bool reuses_none = false;
};

/// Which readings beside the baseline a run holds (--sensitivity): "none"; "strength" (the
/// default: the push strengths that were tried, 0.4x and 2x the baseline's, 0.02 and 0.1 N at the
/// scene's 0.05 N); "all" (every open choice: see variants()).
bool is_sensitivity_set(const std::string& name);

/// The baseline first, then the variants of the set `which` ("none", "strength", "all"). "all":
/// elasticity as restitution; the wind in total; push 0.4x and 2x; swirl rate 0.5x and 2x; drag
/// 0.5x and 2x; heading diffusion 0 and 4x; hung by its two top corners (three nodes each) on `cloth`.
std::vector<Variant> variants(const Interpretation& baseline, const ClothGridSpec& cloth, const std::string& which);

struct SensitivityRow {
  std::string variant, detector;
  std::vector<Claim> claims;
};

struct Robustness {
  std::string id;
  std::string status;  ///< "robust", "fragile", "unsettled"
  int reproduced = 0, not_reproduced = 0, inconclusive = 0;
};

/// Per claim id, in the order of the first row's claims.
std::vector<Robustness> robustness(const std::vector<SensitivityRow>& rows);

}  // namespace tecido::suites::self_contact
