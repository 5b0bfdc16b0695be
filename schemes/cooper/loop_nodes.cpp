#include "schemes/cooper/loop_nodes.h"

#include "framework/core/error.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace cooperage::cooper {
namespace {

[[noreturn]] void fail(int volume_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(volume_id), message);
}

}  // namespace

std::vector<int> seam_curves(const geom::Loop& loop) {
  std::map<int, int> uses;
  for (const auto& use : loop.uses) ++uses[use.curve];
  std::vector<int> seams;
  for (const auto& [curve, n] : uses) {
    if (n == 2) seams.push_back(curve);
  }
  return seams;
}

int single_seam(const geom::Surface& surface) {
  std::vector<int> seams;
  for (const auto& loop : surface.loops) {
    for (int c : seam_curves(loop)) seams.push_back(c);
  }
  return seams.size() == 1 ? seams.front() : 0;
}

std::vector<std::vector<int>> loop_nodes(const geom::Model& model, const mesh::MeshDB& db,
                                         int volume_id, int surface_id) {
  std::vector<std::vector<int>> loops;
  for (const auto& loop : model.surface(surface_id).loops) {
    // A seam (a curve used both ways in one loop, on a periodic face) is no
    // boundary: the runs between its uses are the loops (an annulus on a
    // cone or sphere has one CAD loop and two node loops).
    const std::vector<int> seams = seam_curves(loop);
    auto is_seam = [&](int curve) { return std::binary_search(seams.begin(), seams.end(), curve); };
    std::vector<std::vector<const geom::CurveUse*>> runs(1);
    for (const auto& use : loop.uses) {
      if (is_seam(use.curve)) {
        if (!runs.back().empty()) runs.emplace_back();
        continue;
      }
      runs.back().push_back(&use);
    }
    if (runs.size() > 1 && !runs.back().empty() && !is_seam(loop.uses.front().curve)) {
      // The loop started inside a run: the last run continues into the first.
      runs.front().insert(runs.front().begin(), runs.back().begin(), runs.back().end());
      runs.pop_back();
    }
    std::vector<std::vector<int>> split;
    for (const auto& run : runs) {
      if (run.empty()) continue;
      std::vector<int> nodes;
      for (const geom::CurveUse* use : run) {
        if (!db.curve_meshed(use->curve)) {
          fail(volume_id, "curve " + std::to_string(use->curve) + " of surface " +
                              std::to_string(surface_id) + " is not meshed");
        }
        std::vector<int> chain = db.curve_nodes(use->curve);
        if (use->sense == geom::Sense::Reversed) std::reverse(chain.begin(), chain.end());
        if (!nodes.empty() && chain.front() != nodes.back()) {
          fail(volume_id, "the loop of surface " + std::to_string(surface_id) +
                              " is not closed at curve " + std::to_string(use->curve));
        }
        if (!nodes.empty()) nodes.pop_back();
        nodes.insert(nodes.end(), chain.begin(), chain.end());
      }
      if (nodes.size() > 1 && nodes.front() == nodes.back()) {
        nodes.pop_back();
      } else if (runs.size() > 1) {
        fail(volume_id, "the loop of surface " + std::to_string(surface_id) +
                            " does not close between the uses of its seam");
      }
      split.push_back(std::move(nodes));
    }
    if (split.size() > 1) {
      // The widest loop first: it bounds the others (the outer loop).
      auto extent = [&](const std::vector<int>& l) {
        geom::Vec3 lo = db.node(l.front()), hi = lo;
        for (int n : l) {
          lo = lo.cwiseMin(db.node(n));
          hi = hi.cwiseMax(db.node(n));
        }
        return (hi - lo).norm();
      };
      std::stable_sort(split.begin(), split.end(),
                       [&](const auto& a, const auto& b) { return extent(a) > extent(b); });
    }
    loops.insert(loops.end(), split.begin(), split.end());
  }
  return loops;
}

std::vector<std::vector<int>> quad_boundary_loops(const std::vector<std::array<int, 4>>& quads) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& q : quads) {
    for (size_t k = 0; k < 4; ++k)
      ++count[{std::min(q[k], q[(k + 1) % 4]), std::max(q[k], q[(k + 1) % 4])}];
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

std::vector<std::vector<int>> merge_loops(const std::vector<std::vector<int>>& reference,
                                          const std::vector<std::vector<int>>& others) {
  auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  std::map<std::pair<int, int>, int> count;
  for (const auto* set : {&reference, &others}) {
    for (const auto& l : *set) {
      for (size_t k = 0; k < l.size(); ++k) ++count[key(l[k], l[(k + 1) % l.size()])];
    }
  }
  std::map<int, std::vector<int>> next;  // the edges used once, both ways
  for (const auto& [e, n] : count) {
    if (n != 1) continue;
    next[e.first].push_back(e.second);
    next[e.second].push_back(e.first);
  }
  for (const auto& [v, w] : next) {
    if (w.size() != 2) return {};  // a pinch or an open end: not simple loops
  }
  std::vector<std::vector<int>> loops;
  std::set<int> done;
  for (const auto& [start, w] : next) {
    if (done.count(start)) continue;
    std::vector<int> loop{start};
    done.insert(start);
    for (int prev = start, at = w.front(); at != start;) {
      loop.push_back(at);
      done.insert(at);
      const auto& n = next.at(at);
      const int to = n[0] == prev ? n[1] : n[0];
      prev = at;
      at = to;
    }
    // Orientation: as the reference loop that runs along one of its edges.
    for (size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      int sense = 0;
      for (const auto& r : reference) {
        const auto it = std::find(r.begin(), r.end(), a);
        if (it == r.end()) continue;
        const size_t i = static_cast<size_t>(it - r.begin());
        if (r[(i + 1) % r.size()] == b) sense = 1;
        if (r[(i + r.size() - 1) % r.size()] == b) sense = -1;
      }
      if (sense == 0) continue;
      if (sense < 0) std::reverse(loop.begin(), loop.end());
      break;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace cooperage::cooper
