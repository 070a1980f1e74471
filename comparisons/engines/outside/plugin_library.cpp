#include "comparisons/engines/outside/plugin_library.h"

#include "comparisons/engines/outside/engine_error.h"

#include <dlfcn.h>
#include <link.h>

#include <filesystem>
#include <set>

namespace tecido::outside {

namespace {

std::string door_of(const std::string& path) { return "plug-in " + path; }
std::string in_process_door(const std::string& label) { return "in-process " + label; }

void check_abi_version(const std::string& door, const tecido_plugin& table) {
  if (table.abi_version == TECIDO_PLUGIN_ABI_VERSION) return;
  throw EngineError(door, TECIDO_PLUGIN_ENTRY_SYMBOL,
                    "ABI version mismatch: the plug-in was built for ABI " + std::to_string(table.abi_version) +
                        ", this tecido speaks ABI " + std::to_string(TECIDO_PLUGIN_ABI_VERSION) +
                        " (rebuild it against this include/tecido/plugin.h)");
}

/// The file a loaded library came from, as an absolute path, so that a report names it wherever
/// it is read from: a path with a '/' made absolute against the working directory; a bare name
/// the file dlopen found (its link map), or the name itself when that is not known.
std::string loaded_file(const std::string& path, void* handle) {
  std::string file = path;
  if (path.find('/') == std::string::npos) {
    link_map* map = nullptr;
    if (dlinfo(handle, RTLD_DI_LINKMAP, &map) != 0 || !map || !map->l_name || !*map->l_name) return path;
    file = map->l_name;
  }
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(file, ec);
  return ec ? file : abs.lexically_normal().string();
}

/// check_plugin_table's checks, errors naming `door`.
void check_table(const std::string& door, const tecido_plugin& t) {
  if (t.engine_count == 0 || t.engines == nullptr) throw EngineError(door, TECIDO_PLUGIN_ENTRY_SYMBOL, "names no engine");
  if (t.engine_count > 1000) throw EngineError(door, TECIDO_PLUGIN_ENTRY_SYMBOL, "engine_count is absurd (over 1000)");
  std::set<std::string> seen;
  for (std::size_t k = 0; k < t.engine_count; ++k) {
    const tecido_engine& e = t.engines[k];
    const std::string where = "engines[" + std::to_string(k) + "]";
    const std::string name = e.name ? e.name : "";
    if (!valid_engine_name(name))
      throw EngineError(door, where, "engine name \"" + name + "\" is not 1-64 of [A-Za-z0-9_.-]");
    if (!seen.insert(name).second) throw EngineError(door, where, "engine name \"" + name + "\" appears twice");
    const int dyn = (e.create != nullptr) + (e.step != nullptr) + (e.read != nullptr) + (e.destroy != nullptr);
    if (dyn != 0 && dyn != 4)
      throw EngineError(door, where, "engine \"" + name + "\": a dynamics engine needs all of create, step, read, destroy");
    if (!(e.claimed_order >= 0.0 && e.claimed_order <= 100.0))
      throw EngineError(door, where, "engine \"" + name + "\": claimed_order must be in [0, 100] (0 = none)");
    if (!e.tri_tri && !e.segment_plane && !e.ccd_vertex_face && !e.ccd_edge_edge && dyn == 0)
      throw EngineError(door, where, "engine \"" + name + "\" answers nothing (every function pointer is NULL)");
  }
}

}  // namespace

void check_plugin_table(const std::string& path, const tecido_plugin& t) { check_table(door_of(path), t); }

bool valid_engine_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '-') return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '.' || c == '-';
    if (!ok) return false;
  }
  return true;
}

std::shared_ptr<PluginLibrary> PluginLibrary::load(const std::string& path) {
  const std::string door = door_of(path);
  dlerror();
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw EngineError(door, "dlopen", why ? why : "cannot be loaded");
  }
  dlerror();
  void* sym = dlsym(handle, TECIDO_PLUGIN_ENTRY_SYMBOL);
  if (!sym) {
    dlclose(handle);
    throw EngineError(door, TECIDO_PLUGIN_ENTRY_SYMBOL, "symbol not found (a plug-in exports it; include/tecido/plugin.h)");
  }
  using Entry = const tecido_plugin* (*)();
  Entry entry;
  static_assert(sizeof(entry) == sizeof(sym), "function and object pointers differ in size");
  __builtin_memcpy(&entry, &sym, sizeof entry);  // POSIX: dlsym's pointer is the function's
  const tecido_plugin* table = entry();
  if (!table) {
    dlclose(handle);
    throw EngineError(door, TECIDO_PLUGIN_ENTRY_SYMBOL, "returned NULL");
  }
  try {
    check_abi_version(door, *table);
    check_plugin_table(path, *table);
  } catch (...) {
    dlclose(handle);
    throw;
  }
  return std::shared_ptr<PluginLibrary>(new PluginLibrary(loaded_file(path, handle), handle, table));
}

std::shared_ptr<PluginLibrary> PluginLibrary::in_process(const tecido_plugin* table, const std::string& label) {
  const std::string door = in_process_door(label);
  if (!table) throw EngineError(door, "table", "is NULL");
  check_abi_version(door, *table);
  check_table(door, *table);
  return std::shared_ptr<PluginLibrary>(new PluginLibrary(label, nullptr, table));
}

PluginLibrary::~PluginLibrary() {
  if (handle_) dlclose(handle_);
}

std::string PluginLibrary::door() const {
  return (loaded() ? door_of(path_) : in_process_door(path_)) + " (ABI " + std::to_string(table_->abi_version) + ")";
}

}  // namespace tecido::outside
