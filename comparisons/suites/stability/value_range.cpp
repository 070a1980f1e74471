#include "comparisons/suites/stability/value_range.h"

#include <cmath>

namespace tecido::suites::stability {

void ValueRange::add(double v, const std::string& where) {
  if (!std::isfinite(v)) {
    missing((std::isnan(v) ? "NaN at " : "infinite at ") + where);
    return;
  }
  ++count_;
  if (v < lo_) lo_ = v;
  if (v > hi_) hi_ = v;
}

void ValueRange::missing(const std::string& reason) {
  if (reason_.empty()) reason_ = reason;
}

void ValueRange::include(const ValueRange& other) {
  if (!other.complete()) {
    missing(other.reason());
    return;
  }
  add(other.lo_, "");
  add(other.hi_, "");
}

double ValueRange::lo() const { return reason_.empty() ? lo_ : std::nan(""); }

double ValueRange::hi() const { return reason_.empty() ? hi_ : std::nan(""); }

std::string ValueRange::reason() const {
  if (!reason_.empty()) return reason_;
  return count_ == 0 ? "no values" : "";
}

void record(CheckList& checks, const std::string& name, const ValueRange& range, double value) {
  if (range.complete()) {
    checks.set(name, value);
  } else {
    checks.fail(name, range.reason());
  }
}

}  // namespace tecido::suites::stability
