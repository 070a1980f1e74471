#pragma once
/// The outside engines of one run: every engine of every `--plugin PATH` and every
/// `--engine-cmd NAME=COMMAND`, loaded once when the command starts (a library that cannot be
/// loaded, a process that does not answer hello: EngineError, exit 2 before any work). Commands
/// and suites find them here by name, beside the built-in registries, which stay as they are.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/io/json_reader.h"

#include <memory>
#include <string>
#include <vector>

namespace tecido::outside {

/// The command-line options that name outside engines.
struct OutsideOptions {
  std::vector<std::string> plugins;      ///< --plugin PATH (repeatable)
  std::vector<std::string> engine_cmds;  ///< --engine-cmd NAME=COMMAND (repeatable)
  double timeout_seconds = 60.0;         ///< --engine-timeout: longest wait for one reply
  bool any() const { return !plugins.empty() || !engine_cmds.empty(); }
};

class OutsideEngines {
 public:
  OutsideEngines() = default;
  /// Loads every plug-in and starts every process. Names must be unique among outside engines and
  /// differ from `reserved` (the built-in engines' names): io::UsageError otherwise.
  static std::shared_ptr<OutsideEngines> load(const OutsideOptions& options, const std::vector<std::string>& reserved);

  const std::vector<OutsideEnginePtr>& all() const { return engines_; }
  bool empty() const { return engines_.empty(); }
  /// The engine named `name`, or nullptr.
  OutsideEnginePtr find(const std::string& name) const;
  /// The engines with a capability, in load order (plug-ins first, in the order given, then processes).
  std::vector<OutsideEnginePtr> with(bool Capabilities::*capability) const;
  /// Adds an engine (tests; load() uses it). Throws io::UsageError on a repeated name.
  void add(OutsideEnginePtr engine);

 private:
  std::vector<OutsideEnginePtr> engines_;
};

/// What a report says about each engine: {"name","door","claimed_order","answers":[...],"process":bool}.
io::Json doors_json(const OutsideEngines& engines);
/// The same as a Markdown table (empty when there is no outside engine).
std::string doors_markdown(const OutsideEngines& engines);
/// "tri_tri, ccd, dynamics" for one engine.
std::string answers_text(const Capabilities& c);

/// "NAME=COMMAND" split at the first '='; io::UsageError naming --engine-cmd when malformed.
std::pair<std::string, std::string> split_engine_cmd(const std::string& spec);

}  // namespace tecido::outside
