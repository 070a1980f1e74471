#pragma once
/// What makes an agreement suite's disagreements explain themselves: each entry of the file names
/// the engine, its answer and the referee's; per engine, a summary of its disagreements (how many
/// misses and false hits, the first few ids, how many the file kept) and the command that replays
/// exactly them through the suite's query command, with the engine's door (`--plugin`,
/// `--engine-cmd`) and `--of-engine` taking its entries only, so the replay's false negatives and
/// positives are the suite's for that engine (when the file kept them all).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/agreement/table.h"
#include "comparisons/suites/agreement/tally.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tecido::suites::agreement {

/// {"hit": a.hit, <time_key>: a.t or null when a.hit is false}; {"hit"} alone when `time_key` is
/// null (a test without a time, such as tritri's).
io::Json answer_json(const Answer& a, const char* time_key);

/// The labels a disagreement adds to its entry in the file: {"engine", "answer" (the engine's),
/// "referee" (answer_json), "truth" (the referee's hit, which the query commands count against)}.
io::Json disagreement_labels(const std::string& engine, const Disagreement& d, const char* time_key);

/// Adds disagreement_labels(engines[k], kept[k], time_key) to entry k of `doc[list]` (the file as
/// its query command reads it; the readers ignore the labels but "truth").
void label_entries(io::Json& doc, const char* list, const std::vector<std::string>& engines,
                   const std::vector<Disagreement>& kept, const char* time_key);

/// The query command that reruns a suite's file.
struct ReplayCommand {
  std::string command;  ///< "tecido ccd"
  std::string input;    ///< "--queries"
};

/// One engine's disagreements in a suite run.
struct EngineDisagreements {
  std::string engine;
  std::string door_option;  ///< "--plugin /abs/lib.so" or "--engine-cmd 'NAME=CMD'"; "" for a built-in engine
  long misses = 0, false_hits = 0;  ///< found over every family that ran
  long kept = 0;                    ///< of those, the entries in the file
  std::vector<std::string> first_ids;  ///< the first few kept ids, in file order
  long found() const { return misses + false_hits; }
};

/// How many ids EngineDisagreements::first_ids holds at most.
constexpr std::size_t kFirstIds = 5;

/// Per engine of `engines`, in that order, the counts of `misses` and `false_hits` (per engine) and
/// the kept disagreements' ids (`kept_engine[k]` the engine index of `kept_ids[k]`).
std::vector<EngineDisagreements> engine_disagreements(const std::vector<std::string>& engines,
                                                      const std::vector<std::string>& door_options,
                                                      const std::vector<long>& misses,
                                                      const std::vector<long>& false_hits,
                                                      const std::vector<std::size_t>& kept_engine,
                                                      const std::vector<std::string>& kept_ids);

/// engine_disagreements() of an agreement table: each engine's misses and false hits over the
/// families that did not fail, and the kept disagreements (kept_disagreements()) with their ids.
std::vector<EngineDisagreements> table_disagreements(const AgreementTable& table,
                                                     const std::vector<std::string>& door_options,
                                                     const std::vector<Disagreement>& kept,
                                                     const std::vector<std::string>& kept_ids);

/// "<command> <input> <file> --engines <engine> --of-engine <engine>[ <door option>] --json".
std::string replay_command(const ReplayCommand& c, const std::string& file, const EngineDisagreements& e);

/// Per engine with a disagreement, one line for stderr: "<suite>: <engine>: M misses (false
/// negatives), F false hits (false positives); first: id, ...; <kept> of them in <file>; replay:
/// <replay_command>". None when no engine disagrees.
std::vector<std::string> stderr_lines(const std::string& suite, const ReplayCommand& c, const std::string& file,
                                      const std::vector<EngineDisagreements>& engines);

/// The report's Markdown list of the same, one item per engine that disagrees, with `file` as the
/// report names it ("DIR/ccd/disagreements.json"); "" when none.
std::string replay_markdown(const ReplayCommand& c, const std::string& file,
                            const std::vector<EngineDisagreements>& engines);

}  // namespace tecido::suites::agreement
