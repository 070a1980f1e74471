#pragma once
/// One scaffold for the query commands, which ask engines about a file of cases and print every
/// engine's answer to each (`tecido plane --cases`, `tecido tritri --pairs`, `tecido ccd
/// --queries`; docs/design.md section 3): the input option, --engines (checked against the built-in
/// and outside engine names; default every one, in registry order), --json, the outside-engine
/// options (--plugin, --engine-cmd, --engine-timeout), and the rows of {"results":[...]}. A command
/// names what differs: its input, its engines, its own options and how it answers.
#include "comparisons/cli/commands.h"
#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/io/json_reader.h"

#include <cstddef>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tecido::cli {

/// What a query command was asked: the input file, the engines in the order named, the outside
/// engines loaded (an empty set when none), and --of-engine (the one engine whose disagreements
/// are kept from a suite's file; "" for every entry).
struct QueryRequest {
  std::string input;
  std::vector<std::string> engines;
  std::shared_ptr<outside::OutsideEngines> outside;
  std::string of_engine;
};

/// Whether entry id `id` is kept under --of-engine `engine`: a suite names each disagreement
/// "<engine>:<case>", so a replay takes one engine's entries by that prefix; every id is kept when
/// `engine` is empty.
inline bool kept_by_of_engine(const std::string& id, const std::string& engine) {
  return engine.empty() || id.compare(0, engine.size() + 1, engine + ":") == 0;
}

/// The entries kept under --of-engine (in file order).
template <class Entry>
std::vector<Entry> entries_of_engine(std::vector<Entry> entries, const std::string& engine) {
  if (engine.empty()) return entries;
  std::vector<Entry> out;
  for (Entry& e : entries)
    if (kept_by_of_engine(e.id, engine)) out.push_back(std::move(e));
  return out;
}

struct QueryCommand {
  using KnownNames = std::vector<std::string> (*)(const outside::OutsideEngines* outside);
  using Run = std::function<int(const QueryRequest& request)>;
  QueryCommand() = default;
  /// The fields every query command names; the others keep their defaults.
  QueryCommand(std::string name_, std::string summary_, std::string input_option_, std::string input_help_,
               std::vector<std::string> builtin_, std::string engines_note_, KnownNames known_, Run run_)
      : name(std::move(name_)), summary(std::move(summary_)), input_option(std::move(input_option_)),
        input_help(std::move(input_help_)), builtin(std::move(builtin_)), engines_note(std::move(engines_note_)),
        known(known_), run(std::move(run_)) {}

  std::string name;          ///< the subcommand: "plane"
  std::string summary;       ///< its one-line description
  std::string input_option;  ///< "--cases" (required)
  std::string input_help;
  std::vector<std::string> builtin;  ///< built-in engine names, listed in the help of --engines
  std::string engines_note;          ///< what follows that list in the help: ", and outside engines"
  /// Every engine name the command accepts (built-in, then the loaded outside engines').
  KnownNames known = nullptr;
  /// Answers the request and prints; returns the exit code.
  Run run;
  bool input_non_empty = true;  ///< the input option refuses an empty value
  /// The command's own options, added after the input option (ccd: --csv-kind); may be empty.
  std::function<void(CLI::App& sub)> options;
  std::string footer;  ///< the help's footer ("" for none)
};

/// Registers `command` on `app` and returns its runner: loads the outside engines, resolves
/// --engines, then calls command.run.
Command add_query_command(CLI::App& app, QueryCommand command);

/// The names of a registry's engines (anything with a `name`), in its order.
template <class Engine>
std::vector<std::string> engine_names_of(const std::vector<Engine>& engines) {
  std::vector<std::string> names;
  for (const Engine& e : engines) names.push_back(e.name);
  return names;
}

/// Whether an answer says hit (a bool is the hit itself; an answer struct has `hit`).
inline bool answer_hit(bool hit) { return hit; }
template <class Answer>
bool answer_hit(const Answer& a) {
  return a.hit;
}

/// One engine's answers against the entries' truth (a suite's disagreement file carries the
/// referee's answer as "truth"): false positives (hit where the truth is no), false negatives.
struct TruthTally {
  long entries = 0, false_positives = 0, false_negatives = 0, no_answer = 0;
  void add(const std::optional<bool>& answer, bool truth) {
    if (!answer) {
      ++no_answer;
      return;
    }
    ++entries;
    false_positives += *answer && !truth;
    false_negatives += !*answer && truth;
  }
};

/// "tecido <command>: <engine>: F false positives, N false negatives of E <unit>[; no answer on K]".
std::string truth_summary(const std::string& command, const std::string& engine, const TruthTally& t,
                          const std::string& unit);

/// The entries' ids, queries and truths (a truth for each, or none).
template <class Query>
struct QueryBatch {
  std::vector<std::string> ids;
  std::vector<Query> queries;
  std::vector<std::optional<bool>> truth;
  /// Every entry carries a truth (and there is one, or --of-engine chose none).
  bool all_truth(bool chosen) const {
    for (const auto& t : truth)
      if (!t) return false;
    return !truth.empty() || chosen;
  }
};

/// Asks each engine of `request` (answer(name, queries, outside): one answer per query, nullopt
/// where it cannot answer) and prints {"results":[{"id": ids[k], "truth"?, "<engine>":
/// cell(answer) | null, ...}]} on one line of stdout. When every entry carries a truth, stderr gets
/// truth_summary() per engine. Returns 0.
template <class Query, class Answer, class Cell>
int print_answers(const QueryRequest& request, const QueryBatch<Query>& batch,
                  std::vector<std::optional<Answer>> (*answer)(const std::string&, const std::vector<Query>&,
                                                               const outside::OutsideEngines*),
                  Cell cell, const std::string& command, const std::string& unit) {
  std::vector<std::vector<std::optional<Answer>>> answers;
  for (const auto& name : request.engines) answers.push_back(answer(name, batch.queries, request.outside.get()));
  const bool with_truth = batch.all_truth(!request.of_engine.empty());
  std::vector<TruthTally> tally(request.engines.size());
  io::Json results = io::Json::array();
  for (std::size_t k = 0; k < batch.ids.size(); ++k) {
    io::Json row{{"id", batch.ids[k]}};
    if (batch.truth[k]) row["truth"] = *batch.truth[k];
    for (std::size_t e = 0; e < request.engines.size(); ++e) {
      const std::optional<Answer>& a = answers[e][k];
      row[request.engines[e]] = a ? io::Json(cell(*a)) : io::Json(nullptr);
      if (with_truth) tally[e].add(a ? std::optional<bool>(answer_hit(*a)) : std::nullopt, *batch.truth[k]);
    }
    results.push_back(std::move(row));
  }
  std::cout << io::Json{{"results", results}}.dump() << "\n";
  if (with_truth)
    for (std::size_t e = 0; e < request.engines.size(); ++e)
      std::cerr << truth_summary(command, request.engines[e], tally[e], unit) << "\n";
  return 0;
}

/// A command's run for an input of entries with ids (and an optional `truth`): load(path) reads
/// them, --of-engine keeps one engine's, to_query(entry) makes each one's query, and
/// print_answers() asks the engines and prints.
template <class Entry, class Query, class Answer, class Cell>
std::function<int(const QueryRequest&)> answer_entries(
    std::vector<Entry> (*load)(const std::string&), Query (*to_query)(const Entry&),
    std::vector<std::optional<Answer>> (*answer)(const std::string&, const std::vector<Query>&,
                                                 const outside::OutsideEngines*),
    Cell cell, std::string command, std::string unit) {
  return [=](const QueryRequest& request) {
    QueryBatch<Query> batch;
    for (const Entry& e : entries_of_engine(load(request.input), request.of_engine)) {
      batch.ids.push_back(e.id);
      batch.queries.push_back(to_query(e));
      batch.truth.push_back(e.truth);
    }
    return print_answers(request, batch, answer, cell, command, unit);
  };
}

}  // namespace tecido::cli
