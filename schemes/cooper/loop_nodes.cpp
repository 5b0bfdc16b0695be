#include "schemes/cooper/loop_nodes.h"

#include "framework/core/error.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

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

std::vector<std::vector<int>> quad_boundary_loops(const std::vector<std::array<int, 4>>& quads) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& q : quads) {
    for (size_t k = 0; k < 4; ++k) ++count[{std::min(q[k], q[(k + 1) % 4]), std::max(q[k], q[(k + 1) % 4])}];
  }
  std::map<int, int> next;  // directed boundary edges
  for (const auto& q : quads) {
    for (size_t k = 0; k < 4; ++k) {
      const int a = q[k], b = q[(k + 1) % 4];
      if (count.at({std::min(a, b), std::max(a, b)}) != 1) continue;
      if (!next.emplace(a, b).second) return {};  // a pinch: not simple loops
    }
  }
  std::vector<std::vector<int>> loops;
  while (!next.empty()) {
    std::vector<int> loop{next.begin()->first};
    while (true) {
      const auto it = next.find(loop.back());
      if (it == next.end()) return {};
      const int b = it->second;
      next.erase(it);
      if (b == loop.front()) break;
      loop.push_back(b);
    }
    loops.push_back(loop);
  }
  return loops;
}

}  // namespace cooperage::cooper
