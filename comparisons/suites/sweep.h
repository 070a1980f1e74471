#pragma once
/// Sweep suites: a suite split into independent cases, so that it runs on every core and, as
/// shards, on many machines (`tecido suite NAME --shard i/n`, joined by `tecido merge`).
///
/// A Sweep is built from the SuiteContext (seed, quick, tolerances) and is three things:
///  - `cases`: how many cases, indexed 0..cases-1 in a fixed order;
///  - `run_case(k)`: case k's result as JSON. It depends on k and the context only (its random
///    inputs come from substream(ctx.seed, ...) of k, never from a generator shared between
///    cases), so it is the same whichever thread, process or machine computes it; it must not
///    write files and may be called from several threads at once;
///  - `assemble(results)`: every case's result, in index order, into the SuiteResult (checks,
///    Markdown, data; plots and side files written under ctx.out_dir).
/// A case that throws does not end the suite: its result becomes {"error": "<what>"} (case_error()
/// tells), and assemble fails the checks that case would have fed, with that reason (check.h).
/// Results always travel through their JSON text (also in an unsharded run), so an unsharded run
/// and the merge of its shards assemble bit-identical values: nlohmann::json writes a double in
/// its shortest round-trip form, and num()/get_num() carry NaN and infinities, which JSON lacks.
/// Wall-clock measurements (the tradeoff suite's cost, tritri's ns per pair) are part of a case's
/// result, so a merged report shows the shards' measurements.
#include "comparisons/suites/suite.h"
#include "core/geometry/types.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace tecido::suites {

struct Sweep {
  std::size_t cases = 0;
  std::function<io::Json(std::size_t k)> run_case;
  std::function<SuiteResult(const std::vector<io::Json>& results)> assemble;
};

/// SweepFn (suite.h) builds a suite's sweep from the context; cheap: no case is run.

/// A double as JSON, losslessly: finite values as numbers, NaN as "nan", infinities as "inf" and
/// "-inf".
io::Json num(double x);
/// The inverse of num(); throws (a nlohmann::json exception) on anything else.
double get_num(const io::Json& j);

/// Positions as a flat array [x0, y0, z0, x1, ...] (num() for each coordinate), and back.
io::Json vec3s_json(const std::vector<Vec3>& xs);
std::vector<Vec3> vec3s_from_json(const io::Json& j);

/// A check as JSON {"name","value","lo","hi","note","reason","tolerance"} (lossless), and back.
io::Json check_json(const Check& c);
Check check_from_json(const io::Json& j);

/// The error of a case that threw ({"error": "..."}), or nullptr for a case that produced a result.
const std::string* case_error(const io::Json& result);

/// Runs the cases `indices` of `sweep` on up to `threads` threads (workers take the next index from
/// a shared counter; each result goes to its own slot, so the output does not depend on the thread
/// count), each result passed through its JSON text. A progress bar labelled `label` ticks per case
/// when `progress` (drawn only when stderr is a terminal). Rethrows the first exception of a case.
std::vector<io::Json> run_sweep_cases(const Sweep& sweep, const std::vector<std::size_t>& indices, int threads,
                                      const std::string& label, bool progress);

/// Every case, then assemble: what `tecido suite NAME` does for a sweep suite.
SuiteResult run_sweep(const SweepFn& make, const SuiteContext& ctx, const std::string& name);

}  // namespace tecido::suites
