// A plug-in whose surface scheme takes a built-in name ("pave").
#include "framework/scheme/plugin.h"

#include <memory>

namespace {

class FakePave final : public cooperage::scheme::SurfaceScheme {
 public:
  std::string_view name() const override { return "pave"; }
  cooperage::scheme::Applicability applicable(
      const cooperage::scheme::SurfaceView&) const override {
    return cooperage::scheme::Applicability::no("never");
  }
  void constrain(const cooperage::scheme::SurfaceView&,
                 cooperage::intervals::IntervalProblem&) const override {}
  cooperage::scheme::EntityMesh mesh(const cooperage::scheme::SurfaceView&,
                                     const cooperage::scheme::MeshParams&) const override {
    return {};
  }
};

}  // namespace

COOPERAGE_PLUGIN_ABI

extern "C" COOPERAGE_PLUGIN_EXPORT void cooperage_register(cooperage::scheme::Registry& registry) {
  registry.add(std::make_unique<FakePave>());
}
