#include "comparisons/suites/agreement/replay.h"

#include "comparisons/engines/outside/door_option.h"

#include <fmt/format.h>

namespace tecido::suites::agreement {

io::Json answer_json(const Answer& a, const char* time_key) {
  io::Json j = {{"hit", a.hit}};
  if (time_key) j[time_key] = a.hit ? io::Json(a.t) : io::Json(nullptr);
  return j;
}

io::Json disagreement_labels(const std::string& engine, const Disagreement& d, const char* time_key) {
  return {{"engine", engine},
          {"answer", answer_json(d.answer, time_key)},
          {"referee", answer_json(d.truth, time_key)},
          {"truth", d.truth.hit}};
}

void label_entries(io::Json& doc, const char* list, const std::vector<std::string>& engines,
                   const std::vector<Disagreement>& kept, const char* time_key) {
  io::Json& entries = doc.at(list);
  for (std::size_t k = 0; k < kept.size(); ++k)
    entries.at(k).update(disagreement_labels(engines.at(kept[k].engine), kept[k], time_key));
}

std::vector<EngineDisagreements> engine_disagreements(const std::vector<std::string>& engines,
                                                      const std::vector<std::string>& door_options,
                                                      const std::vector<long>& misses,
                                                      const std::vector<long>& false_hits,
                                                      const std::vector<std::size_t>& kept_engine,
                                                      const std::vector<std::string>& kept_ids) {
  std::vector<EngineDisagreements> out(engines.size());
  for (std::size_t e = 0; e < engines.size(); ++e)
    out[e] = {engines[e], door_options.at(e), misses.at(e), false_hits.at(e), 0, {}};
  for (std::size_t k = 0; k < kept_engine.size(); ++k) {
    EngineDisagreements& d = out.at(kept_engine[k]);
    ++d.kept;
    if (d.first_ids.size() < kFirstIds) d.first_ids.push_back(kept_ids.at(k));
  }
  return out;
}

std::vector<EngineDisagreements> table_disagreements(const AgreementTable& table,
                                                     const std::vector<std::string>& door_options,
                                                     const std::vector<Disagreement>& kept,
                                                     const std::vector<std::string>& kept_ids) {
  const std::size_t n = table.engines.size();
  std::vector<long> misses(n, 0), false_hits(n, 0);
  for (std::size_t f = 0; f < table.tally.size(); ++f) {
    if (!table.error[f].empty()) continue;
    for (std::size_t e = 0; e < n; ++e) misses[e] += table.tally[f][e].misses, false_hits[e] += table.tally[f][e].false_hits;
  }
  std::vector<std::size_t> kept_engine;
  for (const Disagreement& d : kept) kept_engine.push_back(d.engine);
  return engine_disagreements(table.engines, door_options, misses, false_hits, kept_engine, kept_ids);
}

std::string replay_command(const ReplayCommand& c, const std::string& file, const EngineDisagreements& e) {
  const std::string name = outside::shell_word(e.engine);
  return fmt::format("{} {} {} --engines {} --of-engine {}{} --json", c.command, c.input, outside::shell_word(file),
                     name, name, e.door_option.empty() ? "" : " " + e.door_option);
}

namespace {

/// "M misses (false negatives), F false hits (false positives)".
std::string counts_text(const EngineDisagreements& e) {
  return fmt::format("{} misses (false negatives), {} false hits (false positives)", e.misses, e.false_hits);
}

/// "all in F" or "K of them in F (the file's cap): a replay counts those only".
std::string kept_text(const EngineDisagreements& e, const std::string& file) {
  if (e.kept == e.found()) return "all in " + file;
  return fmt::format("{} of them in {} (the file's cap): its replay counts those only", e.kept, file);
}

std::string ids_text(const EngineDisagreements& e) {
  std::string s;
  for (const std::string& id : e.first_ids) s += (s.empty() ? "" : ", ") + id;
  return e.kept > static_cast<long>(e.first_ids.size()) ? s + ", ..." : s;
}

}  // namespace

std::vector<std::string> stderr_lines(const std::string& suite, const ReplayCommand& c, const std::string& file,
                                      const std::vector<EngineDisagreements>& engines) {
  std::vector<std::string> lines;
  for (const EngineDisagreements& e : engines) {
    if (e.found() == 0) continue;
    std::string line = fmt::format("{}: {}: {}", suite, e.engine, counts_text(e));
    if (!e.first_ids.empty()) line += "; first: " + ids_text(e);
    line += "; " + kept_text(e, file);
    if (e.kept > 0) line += "; replay: " + replay_command(c, file, e);
    lines.push_back(std::move(line));
  }
  return lines;
}

std::string replay_markdown(const ReplayCommand& c, const std::string& file,
                            const std::vector<EngineDisagreements>& engines) {
  std::string md;
  for (const EngineDisagreements& e : engines) {
    if (e.found() == 0) continue;
    md += fmt::format("- `{}`: {}; {}", e.engine, counts_text(e), kept_text(e, "the file"));
    md += e.kept > 0 ? fmt::format("; replay: `{}`\n", replay_command(c, file, e)) : "\n";
  }
  if (md.empty()) return md;
  return "Per engine (each replay takes that engine's entries and door and prints its false positives and negatives "
         "against the referee's answers, the suite's counts when the file kept them all):\n\n" + md + "\n";
}

}  // namespace tecido::suites::agreement
