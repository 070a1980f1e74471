#include "comparisons/cli/query_command.h"

#include "comparisons/cli/option_checks.h"
#include "comparisons/cli/outside_options.h"

namespace tecido::cli {

namespace {
std::string comma_list(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}
}  // namespace

std::string truth_summary(const std::string& command, const std::string& engine, const TruthTally& t,
                          const std::string& unit) {
  std::string s = "tecido " + command + ": " + engine + ": " + std::to_string(t.false_positives) +
                  " false positives, " + std::to_string(t.false_negatives) + " false negatives of " +
                  std::to_string(t.entries) + " " + unit;
  if (t.no_answer) s += "; no answer on " + std::to_string(t.no_answer);
  return s;
}

Command add_query_command(CLI::App& app, QueryCommand command) {
  struct Opts {
    std::string input, engines, of_engine;
    bool json = false;
    outside::OutsideOptions outside;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand(command.name, command.summary);
  CLI::Option* input = sub->add_option(command.input_option, o->input, command.input_help)->required();
  if (command.input_non_empty) input->check(non_empty());
  if (command.options) command.options(*sub);
  sub->add_option("--engines", o->engines,
                  "Comma-separated engines (" + comma_list(command.builtin) + command.engines_note +
                      " by name; default: every one)");
  sub->add_option("--of-engine", o->of_engine,
                  "Only the entries whose id starts with \"NAME:\": one engine's disagreements in a suite's "
                  "disagreement file (its replay)")
      ->type_name("NAME");
  sub->add_flag("--json", o->json, "Print JSON (the only output format; kept for the contract)");
  add_outside_options(sub, o->outside);
  if (!command.footer.empty()) sub->footer(command.footer);
  auto c = std::make_shared<const QueryCommand>(std::move(command));
  return [o, c]() {
    QueryRequest request;
    request.input = o->input;
    request.of_engine = o->of_engine;
    request.outside = load_outside_engines(o->outside);
    const std::vector<std::string> known = c->known(request.outside.get());
    request.engines = parse_engine_list(o->engines.empty() ? comma_list(known) : o->engines, known, c->name);
    return c->run(request);
  };
}

}  // namespace tecido::cli
