#pragma once
// An outside engine that claims dynamics and refuses every scene with a fixed reason: what a
// suite must report as "not modelled by refuser: springs: not modelled".
#include "comparisons/engines/outside/outside_engine.h"

#include <string>

namespace tecido::testing {

class RefusingEngine final : public outside::OutsideEngine {
 public:
  const std::string& name() const override { return name_; }
  std::string door() const override { return "test"; }
  bool is_process() const override { return false; }
  outside::Capabilities capabilities() const override { return {false, false, false, false, true}; }
  std::optional<double> claimed_order() const override { return std::nullopt; }
  std::vector<std::optional<bool>> tri_tri(const std::vector<outside::TriTriQuery>&) override { return {}; }
  std::vector<std::optional<SegmentPlaneHit>> segment_plane(const std::vector<outside::SegmentPlaneQuery>&) override {
    return {};
  }
  std::vector<std::optional<CcdAnswer>> ccd(const std::vector<CcdQuery>&) override { return {}; }
  outside::Creation create(const Scene&) override { return {nullptr, "springs: not modelled"}; }

 private:
  std::string name_ = "refuser";
};

}  // namespace tecido::testing
