#include "comparisons/suites/check.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tecido::suites {

namespace {
std::string non_finite_reason(double v) {
  return std::isnan(v) ? "value is NaN" : (v > 0 ? "value is +inf" : "value is -inf");
}
}  // namespace

Check make_check(std::string name, double value, double lo, double hi, std::string note) {
  Check c;
  c.name = std::move(name);
  c.value = value;
  c.lo = lo;
  c.hi = hi;
  c.pass = std::isfinite(value) && value >= lo && value <= hi;
  if (!std::isfinite(value)) c.reason = non_finite_reason(value);
  c.note = std::move(note);
  return c;
}

void CheckList::declare(const std::string& name, const Band& band, std::string note) {
  if (index_.count(name)) throw std::logic_error("check declared twice: " + name);
  index_[name] = checks_.size();
  Entry e;
  e.check.name = name;
  e.check.value = std::numeric_limits<double>::quiet_NaN();
  e.check.lo = band.lo;
  e.check.hi = band.hi;
  e.check.note = std::move(note);
  e.check.tolerance = band.source;
  checks_.push_back(std::move(e));
}

CheckList::Entry& CheckList::entry(const std::string& name) {
  const auto it = index_.find(name);
  if (it == index_.end()) throw std::logic_error("check not declared: " + name);
  return checks_[it->second];
}

void CheckList::set(const std::string& name, double value) {
  Entry& e = entry(name);
  if (e.done) throw std::logic_error("check given two results: " + name);
  e.done = true;
  const Check c = make_check(e.check.name, value, e.check.lo, e.check.hi, e.check.note);
  e.check.value = c.value;
  e.check.pass = c.pass;
  e.check.reason = c.reason;
}

void CheckList::fail(const std::string& name, const std::string& reason) {
  Entry& e = entry(name);
  if (e.done) throw std::logic_error("check given two results: " + name);
  e.done = true;
  e.check.pass = false;
  e.check.reason = reason;
}

void CheckList::fail_pending(const std::string& prefix, const std::string& reason) {
  for (Entry& e : checks_) {
    if (e.done || e.check.name.compare(0, prefix.size(), prefix) != 0) continue;
    e.done = true;
    e.check.pass = false;
    e.check.reason = reason;
  }
}

std::vector<Check> CheckList::finish() const {
  std::vector<Check> out;
  out.reserve(checks_.size());
  for (const Entry& e : checks_) {
    Check c = e.check;
    if (!e.done) {
      c.pass = false;
      c.reason = "not produced";
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace tecido::suites
