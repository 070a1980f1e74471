#include "comparisons/engines/outside/outside_engines.h"

#include "comparisons/engines/outside/plugin_engine.h"
#include "comparisons/engines/outside/plugin_library.h"
#include "comparisons/engines/outside/process_engine.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tecido::outside {

std::pair<std::string, std::string> split_engine_cmd(const std::string& spec) {
  const std::size_t eq = spec.find('=');
  if (eq == std::string::npos)
    throw io::UsageError("--engine-cmd: expected NAME=COMMAND, got \"" + spec + "\"");
  std::string name = spec.substr(0, eq), command = spec.substr(eq + 1);
  if (!valid_engine_name(name))
    throw io::UsageError("--engine-cmd: engine name \"" + name + "\" is not 1-64 of [A-Za-z0-9_.-]");
  if (command.find_first_not_of(" \t") == std::string::npos)
    throw io::UsageError("--engine-cmd " + name + ": the command is empty");
  return {name, command};
}

std::shared_ptr<OutsideEngines> OutsideEngines::load(const OutsideOptions& options,
                                                     const std::vector<std::string>& reserved) {
  if (!(options.timeout_seconds > 0.0) || !std::isfinite(options.timeout_seconds))
    throw io::UsageError("--engine-timeout: must be a number of seconds > 0");
  auto set = std::make_shared<OutsideEngines>();
  auto check = [&](const OutsideEnginePtr& e, const std::string& door) {
    if (std::find(reserved.begin(), reserved.end(), e->name()) != reserved.end())
      throw io::UsageError(door + ": engine name \"" + e->name() + "\" is a built-in engine's; rename it");
    set->add(e);
  };
  for (const std::string& path : options.plugins) {
    const auto library = PluginLibrary::load(path);
    for (const auto& e : plugin_engines(library)) check(e, "--plugin " + path);
  }
  // Names are checked before any process starts.
  std::vector<std::pair<std::string, std::string>> cmds;
  for (const std::string& spec : options.engine_cmds) cmds.push_back(split_engine_cmd(spec));
  for (const auto& [name, command] : cmds) {
    if (set->find(name) || std::find(reserved.begin(), reserved.end(), name) != reserved.end())
      throw io::UsageError("--engine-cmd " + name + ": the name is taken by another engine");
    check(ProcessEngine::start(name, command, std::chrono::duration<double>(options.timeout_seconds)),
          "--engine-cmd " + name);
  }
  return set;
}

OutsideEnginePtr OutsideEngines::find(const std::string& name) const {
  for (const auto& e : engines_)
    if (e->name() == name) return e;
  return nullptr;
}

std::vector<OutsideEnginePtr> OutsideEngines::with(bool Capabilities::*capability) const {
  std::vector<OutsideEnginePtr> out;
  for (const auto& e : engines_)
    if (e->capabilities().*capability) out.push_back(e);
  return out;
}

void OutsideEngines::add(OutsideEnginePtr engine) {
  if (find(engine->name())) throw io::UsageError("outside engine name \"" + engine->name() + "\" given twice");
  engines_.push_back(std::move(engine));
}

std::string answers_text(const Capabilities& c) {
  std::string s;
  auto add = [&](bool on, const char* what) {
    if (on) s += (s.empty() ? "" : ", ") + std::string(what);
  };
  add(c.tri_tri, "tri_tri");
  add(c.segment_plane, "plane");
  add(c.ccd_vertex_face && c.ccd_edge_edge, "ccd");
  add(c.ccd_vertex_face && !c.ccd_edge_edge, "ccd vertex-face");
  add(c.ccd_edge_edge && !c.ccd_vertex_face, "ccd edge-edge");
  add(c.dynamics, "dynamics");
  return s;
}

io::Json doors_json(const OutsideEngines& engines) {
  io::Json a = io::Json::array();
  for (const auto& e : engines.all()) {
    const auto order = e->claimed_order();
    a.push_back({{"name", e->name()},
                 {"door", e->door()},
                 {"process", e->is_process()},
                 {"claimed_order", order ? io::Json(*order) : io::Json(nullptr)},
                 {"answers", answers_text(e->capabilities())}});
  }
  return a;
}

std::string doors_markdown(const OutsideEngines& engines) {
  if (engines.empty()) return "";
  std::string md =
      "## Outside engines\n\nEngines from outside tecido's tree, named with the door each came through (trace a "
      "result to the library or command that produced it). A process engine's costs include the round trips of its "
      "door.\n\n| engine | door | answers | claimed order |\n|---|---|---|---:|\n";
  for (const auto& e : engines.all()) {
    const auto order = e->claimed_order();
    std::string door = e->door();
    for (std::size_t k = door.find('|'); k != std::string::npos; k = door.find('|', k + 2)) door.replace(k, 1, "\\|");
    md += fmt::format("| {} | {} | {} | {} |\n", e->name(), door, answers_text(e->capabilities()),
                      order ? fmt::format("{:g}", *order) : "–");
  }
  return md + "\n";
}

}  // namespace tecido::outside
