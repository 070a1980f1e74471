#include "comparisons/suites/suite_shard.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/shard_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace tecido::suites {

namespace {

constexpr const char* kFormat = "tecido-suite-shard";

io::Json settings_json(const SuiteContext& ctx) {
  return {{"seed", ctx.seed},
          {"quick", ctx.quick},
          {"data", ctx.data_dir},
          {"tolerances",
           {{"file", ctx.tolerances ? ctx.tolerances->file() : std::string()},
            {"contents", ctx.tolerances ? ctx.tolerances->doc() : io::Json::object()}}}};
}

}  // namespace

std::vector<std::size_t> shard_indices(std::size_t cases, int shard_index, int shard_count) {
  std::vector<std::size_t> out;
  for (std::size_t k = static_cast<std::size_t>(shard_index); k < cases; k += static_cast<std::size_t>(shard_count))
    out.push_back(k);
  return out;
}

std::string suite_shard_json(const std::vector<SuiteSlice>& slices, const SuiteContext& ctx, int shard_index,
                             int shard_count) {
  // Written by hand around dump() so that each case result is one line (results can be long:
  // the tradeoff suite keeps every node's final position).
  std::string out = "{\n\"format\": " + io::Json(kFormat).dump() + ",\n\"shard\": " +
                    io::Json::array({shard_index, shard_count}).dump() + ",\n\"settings\": " + settings_json(ctx).dump() +
                    ",\n\"suites\": [";
  for (std::size_t s = 0; s < slices.size(); ++s) {
    const SuiteSlice& sl = slices[s];
    out += (s ? ",\n" : "\n") + fmt::format("{{\"name\": {}, \"cases\": {}, \"seconds\": {}, \"results\": [",
                                            io::Json(sl.name).dump(), sl.cases, io::Json(sl.seconds).dump());
    for (std::size_t k = 0; k < sl.indices.size(); ++k)
      out += (k ? ",\n" : "\n") + io::Json{{"index", sl.indices[k]}, {"result", sl.results[k]}}.dump();
    out += "\n]}";
  }
  out += "\n]\n}\n";
  return out;
}

bool is_suite_shard(const io::Json& doc) {
  return doc.is_object() && doc.contains("format") && doc["format"] == kFormat;
}

MergedSuites merge_suite_shards(const std::vector<std::string>& files) {
  if (files.empty()) throw io::UsageError("merge: no shard directory given");
  std::vector<ShardFile> shards;
  for (const auto& file : files) {
    ShardFile s;
    s.file = file;
    s.doc = io::read_json_file(file);
    const io::JsonReader rd(file);
    rd.require_object(s.doc, "");
    if (!is_suite_shard(s.doc)) rd.fail("/format", std::string("not a suite shard (expected \"") + kFormat + "\")");
    rd.require(s.doc, "", "shard");
    read_shard_position(rd, s);
    shards.push_back(std::move(s));
  }

  // Same n, each shard once, none missing.
  const ShardFile& first = shards.front();
  const int n = first.count;
  const std::vector<const ShardFile*> by_index = shards_by_index(shards);

  // Same settings; the same suites with the same case counts.
  MergedSuites merged;
  merged.shards = n;
  {
    const io::JsonReader rd(first.file);
    const io::Json& st = rd.require_object(rd.require(first.doc, "", "settings"), "/settings");
    const io::Json& seed = rd.require(st, "/settings", "seed");
    if (!seed.is_number_unsigned()) rd.fail("/settings/seed", "expected an integer >= 0");
    merged.seed = seed.get<std::uint64_t>();
    merged.quick = rd.boolean(rd.require(st, "/settings", "quick"), "/settings/quick");
    merged.data_dir = rd.string(rd.require(st, "/settings", "data"), "/settings/data");
    const io::Json& tol = rd.require_object(rd.require(st, "/settings", "tolerances"), "/settings/tolerances");
    const std::string tol_file = rd.string(rd.require(tol, "/settings/tolerances", "file"), "/settings/tolerances/file");
    merged.tolerances = Tolerances(rd.require_object(rd.require(tol, "/settings/tolerances", "contents"),
                                                     "/settings/tolerances/contents"),
                                   tol_file);
    const io::Json& suites = rd.require_array(rd.require(first.doc, "", "suites"), "/suites");
    for (std::size_t s = 0; s < suites.size(); ++s) {
      const std::string w = io::child("/suites", s);
      const io::Json& j = rd.require_object(suites[s], w);
      SuiteSlice sl;
      sl.name = rd.string(rd.require(j, w, "name"), io::child(w, "name"));
      const auto& reg = suite_registry();
      const auto it = std::find_if(reg.begin(), reg.end(), [&](const SuiteEntry& e) { return e.name == sl.name; });
      if (it == reg.end() || !it->sweep)
        rd.fail(io::child(w, "name"), "\"" + sl.name + "\" is not a suite this build can shard");
      sl.cases = static_cast<std::size_t>(
          rd.integer(rd.require(j, w, "cases"), io::child(w, "cases"), 0, std::numeric_limits<std::int32_t>::max()));
      sl.results.resize(sl.cases);
      for (std::size_t k = 0; k < sl.cases; ++k) sl.indices.push_back(k);
      merged.suites.push_back(std::move(sl));
    }
  }
  for (const auto& s : shards) {
    const io::JsonReader rd(s.file);
    if (rd.require(s.doc, "", "settings") != first.doc["settings"])
      rd.fail("/settings", "run with other settings (seed, quick, data or tolerances) than " + first.file);
    const io::Json& suites = rd.require_array(rd.require(s.doc, "", "suites"), "/suites");
    bool same = suites.size() == merged.suites.size();
    for (std::size_t k = 0; same && k < suites.size(); ++k)
      same = suites[k].is_object() && suites[k].contains("name") && suites[k]["name"] == merged.suites[k].name &&
             suites[k].contains("cases") && suites[k]["cases"] == merged.suites[k].cases;
    if (!same) rd.fail("/suites", "other suites or case counts than " + first.file);
  }

  // Every case exactly once, in its own shard.
  for (std::size_t s = 0; s < merged.suites.size(); ++s) {
    SuiteSlice& sl = merged.suites[s];
    std::vector<const ShardFile*> found(sl.cases, nullptr);
    for (const auto& sh : shards) {
      const io::JsonReader rd(sh.file);
      const std::string w = io::child("/suites", s);
      const io::Json& j = sh.doc["suites"][s];
      sl.seconds += rd.number(rd.require(j, w, "seconds"), io::child(w, "seconds"), 1e12);
      const io::Json& results = rd.require_array(rd.require(j, w, "results"), io::child(w, "results"));
      for (std::size_t r = 0; r < results.size(); ++r) {
        const std::string where = io::child(io::child(w, "results"), r);
        const io::Json& e = rd.require_object(results[r], where);
        if (sl.cases == 0) rd.fail(where, "the suite has no cases");
        const auto k = static_cast<std::size_t>(
            rd.integer(rd.require(e, where, "index"), io::child(where, "index"), 0, static_cast<std::int64_t>(sl.cases) - 1));
        if (static_cast<int>(k % static_cast<std::size_t>(n)) != sh.index)
          rd.fail(io::child(where, "index"), fmt::format("{} case {} belongs to shard {}/{}, not {}/{}", sl.name, k,
                                                         k % static_cast<std::size_t>(n), n, sh.index, n));
        if (found[k])
          rd.fail(io::child(where, "index"), fmt::format("{} case {} appears twice (also in {})", sl.name, k, found[k]->file));
        found[k] = &sh;
        sl.results[k] = rd.require(e, where, "result");
      }
    }
    for (std::size_t k = 0; k < sl.cases; ++k)
      if (!found[k])
        throw io::InputError(by_index[k % static_cast<std::size_t>(n)]->file, io::child("/suites", s),
                             fmt::format("{} case {} is missing (it belongs to shard {}/{})", sl.name, k,
                                         k % static_cast<std::size_t>(n), n));
  }
  return merged;
}

}  // namespace tecido::suites
