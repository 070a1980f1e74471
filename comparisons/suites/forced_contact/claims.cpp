#include "comparisons/suites/forced_contact/claims.h"

#include "comparisons/suites/forced_contact/recovery.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::suites::forced_contact {

namespace {

using self_contact::summarize;

int response_index(const Settings& s, SelfCollisionResponse r) {
  const auto it = std::find(s.responses.begin(), s.responses.end(), r);
  return it == s.responses.end() ? -1 : static_cast<int>(it - s.responses.begin());
}

double y(const RunTable& runs, const Settings& s, int h, int r, int k) {
  const RunResult* run = r < 0 ? nullptr : runs[h][r][k];
  return run ? restricted_time(*run, censor_time(s)) : self_contact::kNaN;
}

/// Per run index k (and per hold when `holds` lists several): y(h, a, k) - y(h2, b, k), NaN pairs left out.
std::vector<double> differences(const RunTable& runs, const Settings& s, int a, int ha, int b, int hb, bool every_hold) {
  std::vector<double> out;
  const int holds = static_cast<int>(runs.size());
  for (int h = 0; h < (every_hold ? holds : 1); ++h)
    for (int k = 0; k < s.seeds; ++k) {
      const double d = y(runs, s, every_hold ? h : ha, a, k) - y(runs, s, every_hold ? h : hb, b, k);
      if (!std::isnan(d)) out.push_back(d);
    }
  return out;
}

/// Fills the claim's numbers from values (mean, 95% t interval, n) and decides by `rule`.
template <class Rule>
void decide(Claim& c, const std::vector<double>& values, Rule rule) {
  const Summary m = summarize(values);
  c.observed = m.mean;
  c.ci95 = m.ci95;
  c.n = m.n;
  if (m.n < 2) {
    c.verdict = Verdict::Inconclusive;
    c.reason = fmt::format("no 95% interval: {} value(s) (2 needed)", m.n);
  } else if (m.sd == 0.0) {
    c.verdict = Verdict::Inconclusive;
    c.reason = fmt::format("the {} values do not vary (sd = 0): a zero-width interval decides nothing", m.n);
  } else {
    c.verdict = rule(m.ci95);
  }
}

Claim base(const char* id, const char* statement, const char* unit) {
  Claim c;
  c.id = id;
  c.statement = statement;
  c.unit = unit;
  c.seed_text = "no number; the seed argues it (3.1.3, fig. 16)";
  return c;
}

Claim gia_recovers(const RunTable& runs, const Settings& s) {
  Claim c = base("gia-recovers", "GIA recovers after release: the cloth ends free of self-intersection.", "share of runs");
  const int g = response_index(s, SelfCollisionResponse::Gia);
  int k = 0, n = 0;
  for (const auto& by_response : runs)
    for (const RunResult* r : by_response[g]) {
      if (!r || r->status != "ok") continue;
      ++n;
      k += r->recovered;
    }
  c.observed = n ? static_cast<double>(k) / n : self_contact::kNaN;
  c.ci95 = self_contact::wilson_ci95(k, n);
  c.n = static_cast<std::size_t>(n);
  c.observed_text = fmt::format("{} of {} stable GIA runs recovered within {} s after release", k, n, censor_time(s));
  c.rule = fmt::format("threshold: the share of GIA runs (every hold) that recover, Wilson 95% score interval; reproduced "
                       "if it lies above {:.2f}, not reproduced if below, inconclusive otherwise.", s.recovers_share);
  c.verdict = n < 1 ? Verdict::Inconclusive : self_contact::threshold_verdict(c.ci95, s.recovers_share);
  if (n < 1) c.reason = "no stable GIA run";
  return c;
}

Claim impulse_later(const RunTable& runs, const Settings& s) {
  Claim c = base("impulse-later",
                 "The history-based response (continuous impulse) recovers less often or later than GIA.",
                 "seconds (restricted recovery time, impulse - GIA)");
  const int g = response_index(s, SelfCollisionResponse::Gia), i = response_index(s, SelfCollisionResponse::Impulse);
  const auto d = differences(runs, s, i, 0, g, 0, true);
  c.rule = fmt::format("direction: per (hold, run index) the restricted recovery time (censored at {} s) of impulse minus "
                       "GIA's, 95% t interval over the {} pairs; reproduced if it lies above 0, not reproduced if below, "
                       "inconclusive otherwise.", censor_time(s), d.size());
  decide(c, d, [](const Interval& ci) { return self_contact::direction_verdict(ci, self_contact::kNaN, +1); });
  return c;
}

Claim hold_claim(const RunTable& runs, const Settings& s, SelfCollisionResponse resp, bool level) {
  const int r = response_index(s, resp), last = static_cast<int>(runs.size()) - 1;
  Claim c = level ? base("gia-hold-level", "GIA does not depend on how long the forced state lasted.",
                         "seconds (restricted recovery time, longest hold - shortest)")
                  : base("impulse-hold", "The longer the forced state lasts, the worse the history-based response does.",
                         "seconds (restricted recovery time, longest hold - shortest)");
  const auto d = differences(runs, s, r, last, r, 0, false);
  c.observed_text = fmt::format("holds {} s against {} s", s.holds.back(), s.holds.front());
  if (level) {
    c.rule = fmt::format("equivalence (TOST, margin stated in advance): per run index the restricted recovery time at the "
                         "longest hold minus the shortest, 95% t interval over {} runs; reproduced if it lies inside "
                         "+-{} s, not reproduced if wholly outside, inconclusive otherwise.", d.size(), s.hold_margin);
    decide(c, d, [&](const Interval& ci) { return self_contact::negligible_verdict(ci, s.hold_margin); });
  } else {
    c.rule = fmt::format("direction: per run index the restricted recovery time at the longest hold minus the shortest, "
                         "95% t interval over {} runs; reproduced if it lies above 0, not reproduced if below, "
                         "inconclusive otherwise.", d.size());
    decide(c, d, [](const Interval& ci) { return self_contact::direction_verdict(ci, self_contact::kNaN, +1); });
  }
  return c;
}

}  // namespace

std::vector<Claim> forced_claims(const RunTable& runs, const Settings& s) {
  return {gia_recovers(runs, s), impulse_later(runs, s), hold_claim(runs, s, SelfCollisionResponse::Impulse, false),
          hold_claim(runs, s, SelfCollisionResponse::Gia, true)};
}

}  // namespace tecido::suites::forced_contact
