#pragma once
/// A plug-in shared library, loaded with dlopen: its entry (TECIDO_PLUGIN_ENTRY_SYMBOL), its ABI
/// version checked against TECIDO_PLUGIN_ABI_VERSION, and its engine table checked (names, and a
/// dynamics engine having all four of create/step/read/destroy). Any failure is one EngineError
/// naming the path and what failed: the library cannot be loaded (dlerror's text), the symbol is
/// missing, the version differs, the table is malformed. The library stays loaded while a
/// PluginLibrary (shared by its engines) lives.
#include <tecido/plugin.h>

#include <memory>
#include <string>

namespace tecido::outside {

class PluginLibrary {
 public:
  /// Loads `path` (a path with a '/' is opened as given; a bare name is searched as dlopen does).
  static std::shared_ptr<PluginLibrary> load(const std::string& path);
  /// A table of this very process (the harness library registers its caller's engines so,
  /// include/tecido/harness.h): checked as load() checks a library's table, its version included;
  /// nothing is loaded. `label` names it in errors and reports ("in-process LABEL (ABI N)"). The
  /// table must outlive the PluginLibrary and its engines.
  static std::shared_ptr<PluginLibrary> in_process(const tecido_plugin* table, const std::string& label);
  ~PluginLibrary();
  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;

  /// Whether the table came from a loaded file (false: in_process()).
  bool loaded() const { return handle_ != nullptr; }
  /// The loaded file's absolute path (as given when it could not be found out); in_process(): the label.
  const std::string& path() const { return path_; }
  const tecido_plugin& table() const { return *table_; }
  /// "plug-in PATH (ABI N)", PATH absolute: what a report names.
  std::string door() const;

 private:
  PluginLibrary(std::string path, void* handle, const tecido_plugin* table)
      : path_(std::move(path)), handle_(handle), table_(table) {}
  std::string path_;
  void* handle_ = nullptr;
  const tecido_plugin* table_ = nullptr;
};

/// The checks load() makes on a plug-in's engine table once its ABI version matches: at least
/// one engine and at most 1000, valid and distinct names, a dynamics engine with all four of
/// create/step/read/destroy, claimed_order in [0, 100], some function per engine. Throws
/// EngineError naming `path` and the first problem. (Separate so that fuzz_plugin_table can
/// check it without a shared library.)
void check_plugin_table(const std::string& path, const tecido_plugin& table);

/// Whether `name` is a valid engine name: 1 to 64 of [A-Za-z0-9_.-], not starting with '-'.
bool valid_engine_name(const std::string& name);

}  // namespace tecido::outside
