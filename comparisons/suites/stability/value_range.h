#pragma once
/// The smallest and largest of a set of measured values that cannot hide a missing one.
///
/// std::min and std::max drop a NaN (every comparison with it is false), so a grid cell that
/// produced NaN would silently leave a min/max check. A ValueRange instead remembers the first value
/// that is missing or not finite, and where it came from; `record` then fails the check with that
/// reason instead of setting a value.
#include "comparisons/suites/check.h"

#include <limits>
#include <string>

namespace tecido::suites::stability {

class ValueRange {
 public:
  /// Adds a value measured at `where` ("ks = 10 N/m, m = 1 kg"); a NaN or infinity makes the range
  /// missing with the reason "<what> at <where>".
  void add(double v, const std::string& where);
  /// Marks the range missing: a value it needed was never produced (`reason` says which and why).
  void missing(const std::string& reason);
  /// Takes in another range: its extremes, or its reason when it is incomplete.
  void include(const ValueRange& other);
  /// NaN once missing, else the extremes (+inf / -inf for an empty range).
  double lo() const;
  double hi() const;
  /// max/min - 1: NaN once missing.
  double spread() const { return hi() / lo() - 1.0; }
  bool complete() const { return reason_.empty() && count_ > 0; }
  /// Why the range is incomplete ("no values" when nothing was added), or "".
  std::string reason() const;

 private:
  double lo_ = std::numeric_limits<double>::infinity();
  double hi_ = -std::numeric_limits<double>::infinity();
  int count_ = 0;
  std::string reason_;
};

/// Sets `name` to `value` when the range is complete, else fails it with the range's reason.
void record(CheckList& checks, const std::string& name, const ValueRange& range, double value);

}  // namespace tecido::suites::stability
