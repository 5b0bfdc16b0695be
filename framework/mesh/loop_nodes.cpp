#include "framework/mesh/loop_nodes.h"

#include "framework/core/error.h"

#include <algorithm>
#include <string>

namespace cooperage::mesh {
namespace {

[[noreturn]] void fail(int surface_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(surface_id), message);
}

}  // namespace

std::vector<std::vector<int>> surface_loop_nodes(const geom::Model& model, int surface_id,
                                                 const MeshDB& db) {
  std::vector<std::vector<int>> rings;
  const auto& loops = model.surface(surface_id).loops;
  for (size_t l = 0; l < loops.size(); ++l) {
    std::vector<int> ring;
    for (const geom::CurveUse& use : loops[l].uses) {
      if (!db.curve_meshed(use.curve))
        fail(surface_id, "curve " + std::to_string(use.curve) + " is not meshed");
      std::vector<int> chain = db.curve_nodes(use.curve);
      if (chain.size() < 2)
        fail(surface_id, "curve " + std::to_string(use.curve) + " has no intervals");
      if (use.sense == geom::Sense::Reversed) std::reverse(chain.begin(), chain.end());
      if (!ring.empty() && ring.back() != chain.front()) {
        fail(surface_id,
             "curve " + std::to_string(use.curve) + " does not continue loop " + std::to_string(l));
      }
      ring.insert(ring.end(), chain.begin() + (ring.empty() ? 0 : 1), chain.end());
    }
    if (ring.size() < 2 || ring.front() != ring.back()) {
      fail(surface_id, "loop " + std::to_string(l) + " (curves " + loop_curve_list(loops[l]) +
                           ") is not closed");
    }
    ring.pop_back();
    rings.push_back(std::move(ring));
  }
  return rings;
}

std::string loop_curve_list(const geom::Loop& loop) {
  std::string s;
  for (const auto& use : loop.uses) s += (s.empty() ? "" : "+") + std::to_string(use.curve);
  return s;
}

}  // namespace cooperage::mesh
