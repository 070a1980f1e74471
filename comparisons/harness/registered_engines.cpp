#include "comparisons/harness/registered_engines.h"

#include "comparisons/engines/outside/engine_error.h"
#include "comparisons/engines/outside/plugin_engine.h"
#include "comparisons/engines/outside/plugin_library.h"

#include <stdexcept>

namespace tecido::harness {

RegisteredEngines::RegisteredEngines(const std::vector<tecido_engine>& engines) : table_(engines) {
  if (table_.empty()) return;  // run_suites with built-in engines only
  plugin_.abi_version = TECIDO_PLUGIN_ABI_VERSION;
  plugin_.engine_count = table_.size();
  plugin_.engines = table_.empty() ? nullptr : table_.data();
  try {
    engines_ = outside::plugin_engines(outside::PluginLibrary::in_process(&plugin_, "harness table"));
  } catch (const outside::EngineError& e) {
    throw std::invalid_argument(e.what());
  }
}

}  // namespace tecido::harness
