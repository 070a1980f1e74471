#pragma once
/// The comparison suites: each is a name and a function that runs its cases and returns checks
/// (value against an expected [lo, hi] band read from data/tolerances.json), a Markdown section
/// and any plots it wrote. `tecido suite` runs them and writes report.json and report.md.
#include "comparisons/io/json_reader.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tecido::suites {

/// One tolerance check: pass when lo <= value <= hi (a NaN value fails).
struct Check {
  std::string name;  ///< "suite/what/detail"
  double value = 0.0;
  double lo = 0.0, hi = 0.0;
  bool pass = false;
  std::string note;  ///< optional, one line
};

Check make_check(std::string name, double value, double lo, double hi, std::string note = {});

/// Tolerances from data/tolerances.json, looked up by JSON pointer ("/order/band").
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

 private:
  io::Json doc_;
  std::string file_;
};

struct SuiteContext {
  std::string out_dir;     ///< where plots and side files go
  std::string data_dir;    ///< data/ (scenes, tables)
  bool quick = false;      ///< smaller counts, same checks
  std::uint64_t seed = 0;  ///< every random input derives from this
  int threads = 1;
  const Tolerances* tolerances = nullptr;
  bool gnuplot = false;    ///< gnuplot found on PATH
  bool progress = false;   ///< sweep suites draw a progress bar on stderr (only on a terminal)
};

struct SuiteResult {
  std::string name;
  std::vector<Check> checks;
  std::string markdown;            ///< the suite's section of report.md (tables, plot links)
  std::vector<std::string> plots;  ///< file names written under out_dir
  io::Json data = io::Json::object();  ///< extra machine-readable results for report.json
  double seconds = 0.0;            ///< wall time (not part of the determinism promise)
};

using SuiteFn = std::function<SuiteResult(const SuiteContext&)>;
struct Sweep;
using SweepFn = std::function<Sweep(const SuiteContext&)>;

struct SuiteEntry {
  std::string name;
  std::string summary;
  SuiteFn run;
  /// Set for a suite split into cases (comparisons/suites/sweep.h): `run` runs them on ctx.threads
  /// threads; `tecido suite --shard i/n` runs a slice and `tecido merge` assembles the slices.
  SweepFn sweep = nullptr;
};

/// Every registered suite in the order `all` runs them.
const std::vector<SuiteEntry>& suite_registry();

}  // namespace tecido::suites
