#pragma once
/// The tolerance file (data/tolerances.json, or `tecido suite --tolerances FILE`): bands only.
///
/// Every number in the file is one end (or the half width) of some check's band; nothing in it
/// says what a suite runs or for how long (those are the suite's own settings, next to its code).
/// So editing the file changes pass or fail, never the work done or the set of checks reported.
/// The file is a JSON object of sections, each an object of numbers; keys starting with `_` are
/// comments. A band is read through one of the functions below, which records the pointer(s) it
/// came from, so report.json can say where each band lives.
#include "comparisons/io/json_reader.h"

#include <limits>
#include <string>

namespace tecido::suites {

/// A check's band: pass when lo <= value <= hi. `source` names the tolerance entries it came from.
struct Band {
  double lo = 0.0, hi = 0.0;
  std::string source;
};

class Tolerances {
 public:
  Tolerances() = default;
  Tolerances(io::Json doc, std::string file) : doc_(std::move(doc)), file_(std::move(file)) {}
  /// Reads and validates the file (a JSON object of objects of numbers); throws io::InputError.
  static Tolerances load(const std::string& path);
  /// The number at `pointer`; throws io::InputError naming the file when it is missing.
  double get(const std::string& pointer) const;
  const std::string& file() const { return file_; }
  /// The whole document (a suite shard carries it to `tecido merge`).
  const io::Json& doc() const { return doc_; }

  /// [0, x * scale]: an error, count or distance that may not exceed x (times a scale the suite
  /// names, e.g. the step dt when the file holds "contact time error in steps").
  Band at_most(const std::string& pointer, double scale = 1.0) const;
  /// [x, hi]: at least x; `hi` is the quantity's own upper limit (1 for a share, the run length for a
  /// time), never a tolerance.
  Band at_least(const std::string& pointer, double hi = std::numeric_limits<double>::infinity()) const;
  /// [center - x, center + x]: within x of a value the suite's theory predicts.
  Band around(const std::string& pointer, double center) const;
  /// [lo, hi] from two entries.
  Band between(const std::string& lo_pointer, const std::string& hi_pointer) const;

 private:
  io::Json doc_;
  std::string file_;
};

}  // namespace tecido::suites
