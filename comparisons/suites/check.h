#pragma once
/// A suite's checks, declared before anything runs (docs/design.md section 6, "How a check is
/// declared").
///
/// A suite builds a CheckList from its settings alone (suite, --quick, seed): every check's name and
/// band are fixed before a case runs, so the set of checks a report holds never depends on what was
/// measured or on the tolerance file's numbers. Running the cases then sets values. A check whose
/// value is never produced (a case threw, a run went unstable, a grid cell is empty) stays in the
/// report as failed, with the reason beside it; a NaN or infinite value fails too. Nothing can make
/// a declared check vanish.
#include "comparisons/suites/tolerances.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace tecido::suites {

/// One tolerance check: pass when lo <= value <= hi and value is finite.
struct Check {
  std::string name;  ///< "suite/what/detail"
  double value = 0.0;  ///< NaN when no value was produced
  double lo = 0.0, hi = 0.0;
  bool pass = false;
  std::string note;       ///< optional, one line: what the value is
  std::string reason;     ///< why it failed without a usable value ("not produced", "unstable at step 12", ...)
  std::string tolerance;  ///< where the band comes from in the tolerance file ("/drift/momentum_rel")
};

/// A check with a value (pass = finite and inside [lo, hi]; a non-finite value gets a reason).
Check make_check(std::string name, double value, double lo, double hi, std::string note = {});

/// The declared checks of one suite run, in declaration order.
class CheckList {
 public:
  /// Declares a check; declaring a name twice is a programming error (std::logic_error).
  void declare(const std::string& name, const Band& band, std::string note = {});
  /// Records the value of a declared check (std::logic_error for an undeclared name or a second
  /// value: both are bugs in the suite, not results).
  void set(const std::string& name, double value);
  /// Records that the check's value could not be produced, and why. A later set() is an error.
  void fail(const std::string& name, const std::string& reason);
  /// fail() for every declared check whose name starts with `prefix` and has neither a value nor a
  /// reason yet (a case group that threw takes its checks down with a reason, not silently).
  void fail_pending(const std::string& prefix, const std::string& reason);
  bool declared(const std::string& name) const { return index_.count(name) != 0; }
  std::size_t size() const { return checks_.size(); }
  /// Every declared check; one without a value fails with its reason (or "not produced").
  std::vector<Check> finish() const;

 private:
  struct Entry {
    Check check;
    bool done = false;  ///< set() or fail() was called
  };
  Entry& entry(const std::string& name);
  std::vector<Entry> checks_;
  std::unordered_map<std::string, std::size_t> index_;
};

}  // namespace tecido::suites
