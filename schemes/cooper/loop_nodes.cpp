#include "schemes/cooper/loop_nodes.h"

#include "framework/core/error.h"

#include <algorithm>
#include <string>

namespace cooperage::cooper {
namespace {

[[noreturn]] void fail(int volume_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(volume_id), message);
}

}  // namespace

std::vector<std::vector<int>> loop_nodes(const geom::Model& model, const mesh::MeshDB& db,
                                         int volume_id, int surface_id) {
  std::vector<std::vector<int>> loops;
  for (const auto& loop : model.surface(surface_id).loops) {
    std::vector<int> nodes;
    for (const auto& use : loop.uses) {
      if (!db.curve_meshed(use.curve)) {
        fail(volume_id, "curve " + std::to_string(use.curve) + " of surface " +
                            std::to_string(surface_id) + " is not meshed");
      }
      std::vector<int> chain = db.curve_nodes(use.curve);
      if (use.sense == geom::Sense::Reversed) std::reverse(chain.begin(), chain.end());
      if (!nodes.empty() && chain.front() != nodes.back()) {
        fail(volume_id, "the loop of surface " + std::to_string(surface_id) +
                            " is not closed at curve " + std::to_string(use.curve));
      }
      if (!nodes.empty()) nodes.pop_back();
      nodes.insert(nodes.end(), chain.begin(), chain.end());
    }
    if (nodes.size() > 1 && nodes.front() == nodes.back()) nodes.pop_back();
    loops.push_back(std::move(nodes));
  }
  return loops;
}

}  // namespace cooperage::cooper
