#pragma once
/// One engine of a C plug-in behind OutsideEngine: queries call the plug-in's functions in a loop
/// (a function call each: no round trip), dynamics through PluginSimulation. An engine without
/// TECIDO_ENGINE_THREAD_SAFE is called from one thread at a time (a mutex around every call, its
/// simulations' calls included).
#include "comparisons/engines/outside/door_option.h"
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/engines/outside/plugin_library.h"

#include <memory>
#include <mutex>
#include <vector>

namespace tecido::outside {

class PluginEngine final : public OutsideEngine {
 public:
  PluginEngine(std::shared_ptr<PluginLibrary> library, const tecido_engine* engine);

  const std::string& name() const override { return name_; }
  std::string door() const override { return library_->door(); }
  /// "" for an in-process table: no option of the command line brings it back.
  std::string door_option() const override { return library_->loaded() ? plugin_option(library_->path()) : ""; }
  bool is_process() const override { return false; }
  Capabilities capabilities() const override;
  std::optional<double> claimed_order() const override;

  std::vector<std::optional<bool>> tri_tri(const std::vector<TriTriQuery>& queries) override;
  std::vector<std::optional<SegmentPlaneHit>> segment_plane(const std::vector<SegmentPlaneQuery>& queries) override;
  std::vector<std::optional<CcdAnswer>> ccd(const std::vector<CcdQuery>& queries) override;
  Creation create(const Scene& scene) override;

 private:
  /// Held around plug-in calls unless the engine is thread-safe.
  std::unique_lock<std::mutex> guard();
  std::shared_ptr<PluginLibrary> library_;
  const tecido_engine* engine_;
  std::string name_;
  std::shared_ptr<std::mutex> mutex_;  ///< shared with this engine's simulations
};

/// Every engine of `library`, in table order.
std::vector<std::shared_ptr<OutsideEngine>> plugin_engines(const std::shared_ptr<PluginLibrary>& library);

}  // namespace tecido::outside
