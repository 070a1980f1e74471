#pragma once
/// The caller's engine tables (include/tecido/harness.h) as outside engines: one in-process
/// plug-in table holding copies of them (outside::PluginLibrary::in_process), its engines behind
/// the same adapter as a loaded plug-in's (outside::PluginEngine). A malformed table is
/// std::invalid_argument with the plug-in door's one-line message.
#include "comparisons/engines/outside/outside_engine.h"

#include <tecido/plugin.h>

#include <memory>
#include <vector>

namespace tecido::harness {

class RegisteredEngines {
 public:
  explicit RegisteredEngines(const std::vector<tecido_engine>& engines);
  RegisteredEngines(const RegisteredEngines&) = delete;
  RegisteredEngines& operator=(const RegisteredEngines&) = delete;
  /// In table order; valid while this object lives.
  const std::vector<outside::OutsideEnginePtr>& engines() const { return engines_; }

 private:
  std::vector<tecido_engine> table_;
  tecido_plugin plugin_{};
  std::vector<outside::OutsideEnginePtr> engines_;
};

}  // namespace tecido::harness
