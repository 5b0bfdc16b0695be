#include "schemes/map/volume_map.h"

#include "framework/core/error.h"
#include "schemes/map/block_lattice.h"
#include "schemes/map/map_plan.h"
#include "schemes/map/map_sides.h"
#include "framework/mesh/tfi.h"
#include "framework/quality/hex_metrics.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <sstream>

namespace cooperage::map {

using geom::Vec3;
using mesh::Grid3;
using mesh::tfi_3d;
namespace {

std::string volume_name(int id) { return "volume " + std::to_string(id); }

[[noreturn]] void fail(int volume_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(volume_id), message);
}

// Empty when the volume is a mappable block, else the reason; the faces'
// logical sides go to `face_sides` as they are found.
std::string block_problem(const geom::Model& model, int volume_id, double* score,
                          std::map<int, MapSides>& face_sides) {
  const geom::Volume& volume = model.volume(volume_id);
  const std::string name = volume_name(volume_id);
  if (volume.shells.size() != 1) {
    return name + " has " + std::to_string(volume.shells.size()) + " shells; volume map needs one";
  }
  const auto& shell = volume.shells.front();
  if (shell.size() != 6) {
    return name + ": volume map needs 6 mappable surfaces, volume has " +
           std::to_string(shell.size());
  }
  std::map<std::vector<int>, std::vector<int>> side_faces;  // sorted curves -> surfaces
  std::map<int, std::vector<int>> corner_faces;             // vertex -> surfaces
  double worst = 1.0;
  for (const auto& use : shell) {
    const MapSides& sides = face_sides[use.surface] = analyse_map_surface(model, use.surface);
    if (!sides.ok) {
      return name + ": surface " + std::to_string(use.surface) + " is not mappable (" + sides.why +
             ")";
    }
    worst = std::min(worst, sides.score);
    for (const auto& side : sides.sides) {
      std::vector<int> key = side_curves(side);
      std::sort(key.begin(), key.end());
      side_faces[key].push_back(use.surface);
    }
    for (int v : sides.corner_vertices) corner_faces[v].push_back(use.surface);
  }
  for (const auto& [curves, faces] : side_faces) {
    if (faces.size() != 2) {
      return name + ": the logical side along curves " + join_ids(curves) + " is a side of " +
             std::to_string(faces.size()) + " surface(s) (" + join_ids(faces, ", ") +
             "); a block needs each of its 12 edges in exactly 2 faces";
    }
  }
  if (side_faces.size() != 12) {
    return name + ": the surfaces form " + std::to_string(side_faces.size()) +
           " logical edges; a block has 12";
  }
  for (const auto& [vertex, faces] : corner_faces) {
    if (faces.size() != 3) {
      return name + ": vertex " + std::to_string(vertex) + " is a logical corner of " +
             std::to_string(faces.size()) + " surface(s); a block corner is in 3";
    }
  }
  if (corner_faces.size() != 8) {
    return name + ": " + std::to_string(corner_faces.size()) +
           " logical corner vertices; a block has 8";
  }
  if (score) *score = worst;
  return {};
}

struct Analysis {
  std::shared_ptr<const VolumeMapPlan> plan;
  std::string why;  // empty when the volume is a block
  double score = 0.0;
};

Analysis analyse(const scheme::VolumeView& view) {
  Analysis a;
  auto p = std::make_shared<VolumeMapPlan>();
  p->volume_id = view.volume_id;
  a.why = block_problem(view.model, view.volume_id, &a.score, p->faces);
  a.plan = std::move(p);
  return a;
}

}  // namespace

scheme::Applicability VolumeMap::applicable(const scheme::VolumeView& view) const {
  Analysis a = analyse(view);
  if (!a.why.empty()) return scheme::Applicability::no(a.why);
  return scheme::Applicability::yes(
      a.score, volume_name(view.volume_id) + ": 6 mappable surfaces forming a block",
      std::move(a.plan));
}

void VolumeMap::constrain(const scheme::VolumeView& view,
                          intervals::IntervalProblem& problem) const {
  const std::shared_ptr<const VolumeMapPlan> p =
      carried_or<VolumeMapPlan>(view, view.volume_id, [&] { return analyse(view).plan; });
  for (int surface_id : view.model.surfaces_of(view.volume_id)) {
    const auto it = p->faces.find(surface_id);
    if (it != p->faces.end() && it->second.ok) add_map_constraints(surface_id, it->second, problem);
  }
}

scheme::SurfaceRoles VolumeMap::roles(const scheme::VolumeView& view) const {
  scheme::SurfaceRoles roles;
  for (int surface_id : view.model.surfaces_of(view.volume_id)) roles[surface_id] = "map";
  return roles;
}

scheme::EntityMesh VolumeMap::mesh(const scheme::VolumeView& view,
                                   const scheme::Settings& /*params*/) const {
  const int vid = view.volume_id;
  if (!view.mesh) fail(vid, "volume map needs the meshed surfaces");
  const mesh::MeshDB& db = *view.mesh;
  std::vector<mesh::Quad> quads;
  for (int surface_id : view.model.surfaces_of(vid)) {
    if (!db.surface_meshed(surface_id)) {
      fail(vid, "surface " + std::to_string(surface_id) + " is not meshed");
    }
    const mesh::SurfaceMeshData& s = db.surface(surface_id);
    if (!s.tris.empty()) {
      fail(vid, "surface " + std::to_string(surface_id) + " has triangles; volume map needs quads");
    }
    quads.insert(quads.end(), s.quads.begin(), s.quads.end());
  }
  const BlockLattice lattice = recover_block_lattice(quads);
  if (!lattice.ok) fail(vid, "cannot recover the block lattice: " + lattice.why);

  Grid3 grid;
  grid.ni = lattice.ni;
  grid.nj = lattice.nj;
  grid.nk = lattice.nk;
  grid.at.assign(lattice.node.size(), Vec3::Zero());
  for (size_t p = 0; p < lattice.node.size(); ++p) {
    if (lattice.node[p] >= 0) grid.at[p] = db.node(lattice.node[p]);
  }
  tfi_3d(grid);

  scheme::EntityMesh out;
  std::vector<int> local(lattice.node.size());
  for (size_t p = 0; p < lattice.node.size(); ++p) {
    local[p] = out.add(grid.at[p], lattice.node[p]);
  }

  // Handedness: (i x j) . k at the first corner decides which layer is the bottom.
  const Vec3 ei = grid(1, 0, 0) - grid(0, 0, 0);
  const Vec3 ej = grid(0, 1, 0) - grid(0, 0, 0);
  const Vec3 ek = grid(0, 0, 1) - grid(0, 0, 0);
  const bool flip = ei.cross(ej).dot(ek) < 0;

  out.hexes.reserve(static_cast<size_t>(grid.ni) * static_cast<size_t>(grid.nj) *
                    static_cast<size_t>(grid.nk));
  double worst = 2.0;
  std::array<int, 3> worst_at{};
  for (int k = 0; k < grid.nk; ++k) {
    const int kb = flip ? k + 1 : k;
    const int kt = flip ? k : k + 1;
    for (int j = 0; j < grid.nj; ++j) {
      for (int i = 0; i < grid.ni; ++i) {
        const size_t ids[8] = {grid.index(i, j, kb),         grid.index(i + 1, j, kb),
                               grid.index(i + 1, j + 1, kb), grid.index(i, j + 1, kb),
                               grid.index(i, j, kt),         grid.index(i + 1, j, kt),
                               grid.index(i + 1, j + 1, kt), grid.index(i, j + 1, kt)};
        mesh::Hex hex;
        std::array<Vec3, 8> x;
        for (size_t c = 0; c < 8; ++c) {
          hex[c] = local[ids[c]];
          x[c] = grid.at[ids[c]];
        }
        const double sj = quality::hex_scaled_jacobian(x);
        if (sj < worst) {
          worst = sj;
          worst_at = {i, j, k};
        }
        out.hexes.push_back(hex);
      }
    }
  }
  if (worst <= 0.0) {
    std::ostringstream s;
    s << "hex (" << worst_at[0] << ", " << worst_at[1] << ", " << worst_at[2]
      << ") of the mapped block has scaled Jacobian " << worst << " <= 0";
    fail(vid, s.str());
  }
  return out;
}

std::unique_ptr<scheme::VolumeScheme> make_volume_map() { return std::make_unique<VolumeMap>(); }

}  // namespace cooperage::map
