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
/// engines loaded (an empty set when none).
struct QueryRequest {
  std::string input;
  std::vector<std::string> engines;
  std::shared_ptr<outside::OutsideEngines> outside;
};

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

/// Asks each engine of `request` (answer(name, queries, outside): one answer per query, nullopt
/// where it cannot answer) and prints {"results":[{"id": ids[k], "<engine>": cell(answer) | null,
/// ...}]} on one line of stdout. Returns 0.
template <class Query, class Answer, class Cell>
int print_answers(const QueryRequest& request, const std::vector<std::string>& ids, const std::vector<Query>& queries,
                  std::vector<std::optional<Answer>> (*answer)(const std::string&, const std::vector<Query>&,
                                                               const outside::OutsideEngines*),
                  Cell cell) {
  std::vector<std::vector<std::optional<Answer>>> answers;
  for (const auto& name : request.engines) answers.push_back(answer(name, queries, request.outside.get()));
  io::Json results = io::Json::array();
  for (std::size_t k = 0; k < ids.size(); ++k) {
    io::Json row{{"id", ids[k]}};
    for (std::size_t e = 0; e < request.engines.size(); ++e) {
      const std::optional<Answer>& a = answers[e][k];
      row[request.engines[e]] = a ? io::Json(cell(*a)) : io::Json(nullptr);
    }
    results.push_back(std::move(row));
  }
  std::cout << io::Json{{"results", results}}.dump() << "\n";
  return 0;
}

/// A command's run for an input of entries with ids: load(path) reads them, to_query(entry) makes
/// each one's query, and print_answers() asks the engines and prints.
template <class Entry, class Query, class Answer, class Cell>
std::function<int(const QueryRequest&)> answer_entries(
    std::vector<Entry> (*load)(const std::string&), Query (*to_query)(const Entry&),
    std::vector<std::optional<Answer>> (*answer)(const std::string&, const std::vector<Query>&,
                                                 const outside::OutsideEngines*),
    Cell cell) {
  return [=](const QueryRequest& request) {
    std::vector<std::string> ids;
    std::vector<Query> queries;
    for (const Entry& e : load(request.input)) ids.push_back(e.id), queries.push_back(to_query(e));
    return print_answers(request, ids, queries, answer, cell);
  };
}

}  // namespace tecido::cli
