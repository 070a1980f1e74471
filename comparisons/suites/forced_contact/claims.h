#pragma once
/// The seed's argument for GIA (section 3.1.3, fig. 16), as claims stated before the data, each
/// with its rule (the rule families of self_contact/claims.h, the same Claim and Verdict types).
/// A run's outcome is its restricted recovery time y (recovery.h): the time after release from
/// which the cloth stays free of intersection, or the censoring time C when it does not recover,
/// so "recovers less often or later" is one number, larger y. Runs of the same index s start
/// from the same offsets whatever the response and hold, so differences are paired by s.
///  - gia-recovers: GIA recovers after release. Pooled over the holds, the share of GIA runs that
///    recover; threshold rule: Wilson 95% interval above Settings::recovers_share -> reproduced,
///    below -> not reproduced, otherwise inconclusive.
///  - impulse-later: the history-based response (impulse) recovers less often or later than GIA.
///    Per (hold, s): y_impulse - y_gia; 95% t interval over the pairs; direction rule: above 0 ->
///    reproduced, below 0 -> not reproduced, otherwise inconclusive.
///  - impulse-hold: the longer the forced state, the worse the history-based response does.
///    Per s: y_impulse(longest hold) - y_impulse(shortest hold); direction rule, above 0.
///  - gia-hold-level: GIA does not depend on the hold. Per s: y_gia(longest) - y_gia(shortest);
///    equivalence with margin Settings::hold_margin stated in advance: the 95% interval inside
///    +-margin -> reproduced (both one-sided tests of TOST reject at 2.5%, stricter than TOST's
///    usual 90% interval), wholly outside -> not reproduced, otherwise inconclusive.
/// A claim whose values do not vary (sd = 0 with n >= 2: e.g. every run censored) is
/// inconclusive, with that reason: a zero-width interval decides nothing. Fewer than 2 values:
/// inconclusive. Multiplicity: four claims, each decided on its own 95% interval; no adjustment
/// is applied yet (Holm's step-down over the four claims' p-values plugs in where decide() sets
/// the verdict, once the shared Holm function of self_contact/statistics.h exists).
#include "comparisons/suites/forced_contact/run.h"
#include "comparisons/suites/self_contact/claims.h"

#include <vector>

namespace tecido::suites::forced_contact {

using self_contact::Claim;
using self_contact::Verdict;

/// runs[h][r][s]: the run of hold index h, response index r (into Settings::responses), run s;
/// nullptr when it threw.
using RunTable = std::vector<std::vector<std::vector<const RunResult*>>>;

/// The four claims above, in that order.
std::vector<Claim> forced_claims(const RunTable& runs, const Settings& s);

}  // namespace tecido::suites::forced_contact
