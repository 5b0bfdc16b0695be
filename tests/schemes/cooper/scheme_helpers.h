// Registries and settings the cooper tests mesh with (tests only).
#pragma once

#include "framework/io/job.h"
#include "framework/scheme/polygon_mesher.h"
#include "framework/scheme/registry.h"
#include "schemes/builtin_schemes.h"
#include "schemes/pave/pave_2d.h"
#include "support/sized_settings.h"

#include <memory>
#include <vector>

namespace cooperage::testing {

/// pave's 2D core as cooper's polygon mesher, as the registration code is
/// meant to wire it (framework/scheme/polygon_mesher.h).
class Pave2D final : public scheme::PolygonMesher {
 public:
  scheme::QuadMesh2D mesh(const std::vector<std::vector<Eigen::Vector2d>>& loops) const override {
    const pave::QuadMesh2D m = pave::pave_2d(loops);
    return {m.points, m.quads, m.boundary_count};
  }
};

/// Every built-in scheme, wired as the command line wires them.
inline std::unique_ptr<scheme::Registry> builtin() {
  auto r = std::make_unique<scheme::Registry>();
  register_builtin_schemes(*r);
  return r;
}

}  // namespace cooperage::testing
