#pragma once
/// The options that bring outside engines into a command (tritri, plane, ccd, suite), added by one
/// function so every command spells them alike:
///   --plugin PATH.so          a C plug-in (include/tecido/plugin.h); repeatable
///   --engine-cmd NAME=COMMAND a process speaking JSON lines; repeatable
///   --engine-timeout SECONDS  longest wait for one reply of a process (default 60)
#include "comparisons/engines/outside/outside_engines.h"

#include <CLI/CLI.hpp>

#include <memory>

namespace tecido::cli {

void add_outside_options(CLI::App* sub, outside::OutsideOptions& options);

/// Loads what the options name (nothing to load: an empty set); the names of built-in engines are
/// reserved. Throws EngineError / io::UsageError (exit 2).
std::shared_ptr<outside::OutsideEngines> load_outside_engines(const outside::OutsideOptions& options);

}  // namespace tecido::cli
