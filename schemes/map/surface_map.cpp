#include "schemes/map/surface_map.h"

#include "framework/core/error.h"
#include "schemes/map/map_plan.h"
#include "schemes/map/map_sides.h"
#include "framework/mesh/tfi.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace cooperage::map {

using geom::Vec3;
using mesh::Grid2;
using mesh::tfi_2d;
namespace {

[[noreturn]] void fail(int surface_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(surface_id), message);
}

// Node chain of a logical side, from its first corner to its last: the
// curves' chains in loop order (reversed for Reversed uses), junction nodes once.
std::vector<int> side_chain(const mesh::MeshDB& db, int surface_id,
                            const std::vector<geom::CurveUse>& side) {
  std::vector<int> chain;
  for (const auto& use : side) {
    if (!db.curve_meshed(use.curve)) {
      fail(surface_id, "curve " + std::to_string(use.curve) + " is not meshed");
    }
    std::vector<int> nodes = db.curve_nodes(use.curve);
    if (nodes.size() < 2)
      fail(surface_id, "curve " + std::to_string(use.curve) + " has no intervals");
    if (use.sense == geom::Sense::Reversed) std::reverse(nodes.begin(), nodes.end());
    if (!chain.empty()) {
      if (chain.back() != nodes.front()) {
        fail(surface_id, "curve " + std::to_string(use.curve) +
                             " does not continue the node chain of its side");
      }
      chain.insert(chain.end(), nodes.begin() + 1, nodes.end());
    } else {
      chain = std::move(nodes);
    }
  }
  return chain;
}

std::vector<Vec3> points_of(const mesh::MeshDB& db, const std::vector<int>& nodes) {
  std::vector<Vec3> p;
  p.reserve(nodes.size());
  for (int n : nodes) p.push_back(db.node(n));
  return p;
}

std::shared_ptr<const SurfaceMapPlan> plan(const scheme::SurfaceView& view) {
  return carried_or<SurfaceMapPlan>(view, view.surface_id, [&] {
    auto p = std::make_shared<SurfaceMapPlan>();
    p->surface_id = view.surface_id;
    p->sides = analyse_map_surface(view.model, view.surface_id);
    return std::shared_ptr<const SurfaceMapPlan>(std::move(p));
  });
}

}  // namespace

scheme::Applicability SurfaceMap::applicable(const scheme::SurfaceView& view) const {
  std::shared_ptr<const SurfaceMapPlan> p = plan(view);
  const MapSides& sides = p->sides;
  if (!sides.ok) return scheme::Applicability::no(sides.why);
  std::string why = "surface " + std::to_string(view.surface_id) + ": 4 END vertices (" +
                    join_ids({sides.corner_vertices.begin(), sides.corner_vertices.end()}, ", ") +
                    ")";
  return scheme::Applicability::yes(sides.score, std::move(why), std::move(p));
}

void SurfaceMap::constrain(const scheme::SurfaceView& view,
                           intervals::IntervalProblem& problem) const {
  const std::shared_ptr<const SurfaceMapPlan> p = plan(view);
  if (!p->sides.ok) return;  // not ours to mesh; applicable() said why
  add_map_constraints(view.surface_id, p->sides, problem);
}

scheme::EntityMesh SurfaceMap::mesh(const scheme::SurfaceView& view,
                                    const scheme::Settings& /*params*/) const {
  const int sid = view.surface_id;
  if (!view.mesh) fail(sid, "map needs the meshed curves");
  const mesh::MeshDB& db = *view.mesh;
  const std::shared_ptr<const SurfaceMapPlan> planned = plan(view);
  const MapSides& sides = planned->sides;
  if (!sides.ok) fail(sid, "not mappable: " + sides.why);

  std::array<std::vector<int>, 4> chains;
  for (size_t s = 0; s < 4; ++s) chains[s] = side_chain(db, sid, sides.sides[s]);
  for (size_t s = 0; s < 4; ++s) {
    if (chains[s].back() != chains[(s + 1) % 4].front()) {
      fail(sid, "logical sides " + std::to_string(s) + " and " + std::to_string((s + 1) % 4) +
                    " do not meet at a node");
    }
  }
  const int n = static_cast<int>(chains[0].size()) - 1;
  const int m = static_cast<int>(chains[1].size()) - 1;
  if (static_cast<int>(chains[2].size()) - 1 != n || static_cast<int>(chains[3].size()) - 1 != m) {
    fail(sid, "opposite sides differ in intervals: curves " +
                  join_ids(side_curves(sides.sides[0])) + " have " + std::to_string(n) +
                  ", curves " + join_ids(side_curves(sides.sides[2])) + " have " +
                  std::to_string(chains[2].size() - 1) + "; curves " +
                  join_ids(side_curves(sides.sides[1])) + " have " + std::to_string(m) +
                  ", curves " + join_ids(side_curves(sides.sides[3])) + " have " +
                  std::to_string(chains[3].size() - 1));
  }

  // Lattice (i, j): i along side 0, j along side 1; the loop runs
  // counter-clockwise about the natural normal, so i x j follows it.
  std::vector<int> bottom = chains[0];                          // (i, 0)
  std::vector<int> right = chains[1];                           // (n, j)
  std::vector<int> top(chains[2].rbegin(), chains[2].rend());   // (i, m)
  std::vector<int> left(chains[3].rbegin(), chains[3].rend());  // (0, j)
  const Grid2 grid =
      tfi_2d(points_of(db, bottom), points_of(db, top), points_of(db, left), points_of(db, right));

  scheme::EntityMesh out;
  std::unordered_map<int, int> local_of_global;  // seams: one local node per global node
  auto boundary_local = [&](int global) {
    auto it = local_of_global.find(global);
    if (it != local_of_global.end()) return it->second;
    const int local = out.add(db.node(global), global);
    local_of_global.emplace(global, local);
    return local;
  };
  // Node counts in size_t: (n + 1) * (m + 1) overflows int at 65,535 x
  // 65,536 intervals (issue 21); local node ids are int, so refuse beyond.
  const size_t grid_nodes = (static_cast<size_t>(n) + 1) * (static_cast<size_t>(m) + 1);
  if (grid_nodes > static_cast<size_t>(std::numeric_limits<int>::max()))
    fail(sid, std::to_string(n) + " x " + std::to_string(m) +
                  " intervals are more than a mesh can hold");
  const geom::SurfaceGeometry& geometry = *view.surface().geometry;
  std::vector<int> local(grid_nodes);
  auto at = [&](int i, int j) -> int& {
    return local[static_cast<size_t>(i) * (static_cast<size_t>(m) + 1) + static_cast<size_t>(j)];
  };
  // Interior points go onto the surface by a local search from the
  // parameters of the previous point in the row (the row's first from the
  // previous row's first): a neighbour, a fraction of an element away.
  geom::Vec2 previous_uv, row_start_uv;
  auto project_interior = [&](int i, int j) {
    const Vec3 p = grid(i, j);
    const geom::SurfaceProjection pr = j > 1   ? geometry.project_near(p, previous_uv)
                                       : i > 1 ? geometry.project_near(p, row_start_uv)
                                               : geometry.project(p);
    previous_uv = pr.uv;
    if (j == 1) row_start_uv = pr.uv;
    return pr.point;
  };
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= m; ++j) {
      const size_t ui = static_cast<size_t>(i), uj = static_cast<size_t>(j);
      if (j == 0)
        at(i, j) = boundary_local(bottom[ui]);
      else if (j == m)
        at(i, j) = boundary_local(top[ui]);
      else if (i == 0)
        at(i, j) = boundary_local(left[uj]);
      else if (i == n)
        at(i, j) = boundary_local(right[uj]);
      else
        at(i, j) = out.add(project_interior(i, j));
    }
  }
  out.quads.reserve(static_cast<size_t>(n) * static_cast<size_t>(m));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      out.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return out;
}

std::unique_ptr<scheme::SurfaceScheme> make_surface_map() { return std::make_unique<SurfaceMap>(); }

}  // namespace cooperage::map
