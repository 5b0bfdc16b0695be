// The state of one volume's sweep (detail of sweep_volume.h), shared by
// its steps: ribs (barrel_ribs.cpp), imprinting (imprint_barrels.cpp), cap
// stacks (cap_stacks.cpp) and the barrel sweeps (sweep_barrels.cpp).
// Nodes are numbered as in the EntityMesh being built: existing MeshDB
// nodes are added once (`existing`), new nodes are added with an owner.
#pragma once

#include "framework/core/error.h"
#include "framework/scheme/polygon_mesher.h"
#include "framework/scheme/scheme.h"
#include "schemes/cooper/imprint_subcaps.h"
#include "schemes/cooper/least_squares_map.h"
#include "schemes/cooper/plan_volume.h"
#include "schemes/cooper/sweep_volume.h"

#include <array>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace cooperage::cooper::detail {

/// Node -> node of a barrel (the node below each upper-cap node; a cap
/// node's local index): only looked up, never iterated, so hashed.
using NodeImage = std::unordered_map<int, int>;

[[noreturn]] inline void fail(int volume_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(volume_id), message);
}

/// A subcap: a piece of a real cap or of a virtual cap, at the end of one
/// barrel (a real cap) or two (a virtual cap between them).
struct Piece {
  int id = 0;
  int cap = 0;                          ///< real cap face, or 0
  int interface = -1;                   ///< virtual: index into the tree's interfaces
  int upper_of = -1;                    ///< barrel whose upper end holds it, or -1
  int lower_of = -1;                    ///< barrel whose lower end holds it, or -1
  bool premeshed = false;               ///< its cap was meshed by a surface scheme
  bool alive = true;                    ///< false once split into other pieces
  std::vector<std::vector<int>> loops;  ///< node loops, outer first
  /// Its mesh once the stack is meshed (node ids; faces counter-clockwise
  /// about the natural normal of its cap for a real piece, arbitrary else).
  std::vector<mesh::Quad> quads;
  std::vector<mesh::Tri> tris;
  bool meshed = false;
};

/// A barrel while it is being swept.
struct BarrelState {
  int layers = 0;
  std::vector<std::vector<int>> ribs;         ///< MeshDB nodes, upper to lower, layers + 1 each
  std::vector<std::size_t> loop_starts;       ///< first rib of every rib loop
  std::vector<std::vector<int>> upper_loops;  ///< rib starts by loop (node ids)
  std::vector<std::vector<int>> lower_loops;  ///< rib ends by loop (node ids)
  // Chart: both ends in one plane, the lower end mapped onto the upper.
  AffineMap to_lower;
  AffineMap to_upper;
  geom::Vec3 d = geom::Vec3::UnitZ();  ///< from the upper ring's centre to the lower one's
  geom::Vec3 u = geom::Vec3::UnitX();
  geom::Vec3 v = geom::Vec3::UnitY();
  double level = 0;  ///< the upper centre along d
  /// Ribs between the ends (exterior and interior), node ids (upper, lower).
  std::vector<std::pair<int, int>> rib_pairs;
  /// Matched pieces (upper, lower) after imprinting.
  std::vector<std::pair<int, int>> matches;
  /// Node of the lower end under each node of the upper end (all of them,
  /// once the stacks are projected).
  std::map<int, int> below;
  std::vector<ImprintStep> steps;
  /// Imprinted in the chart warped along the ribs (chart_warp.h): the
  /// affine chart's imprinting failed.
  bool warped_chart = false;
};

struct SweepState {
  SweepState(const scheme::VolumeView& view, const VolumePlan& volume_plan,
             const scheme::PolygonMesher* polygon_mesher)
      : vid(view.volume_id),
        model(view.model),
        db(*view.mesh),
        plan(volume_plan),
        mesher(polygon_mesher) {}

  int vid;
  const geom::Model& model;
  const mesh::MeshDB& db;
  const VolumePlan& plan;
  const scheme::PolygonMesher* mesher;
  scheme::EntityMesh out;
  std::unordered_map<int, int> local;  ///< MeshDB node -> out node
  std::vector<BarrelState> barrels;
  std::vector<Piece> pieces;  ///< by id
  /// Interface -> its rib-end loops and the caps inside them (node ids).
  std::vector<std::vector<std::vector<int>>> interface_loops;

  /// The out node of MeshDB node g (added on first use).
  int existing(int g) {
    auto [it, added] = local.emplace(g, 0);
    if (added) it->second = out.add(db.node(g), g);
    return it->second;
  }
  const geom::Vec3& pos(int n) const { return out.coords[static_cast<size_t>(n)]; }
  geom::Vec2 plane(size_t b, const geom::Vec3& x) const {
    const BarrelState& s = barrels[b];
    return {x.dot(s.u), x.dot(s.v)};
  }
  std::string barrel_name(size_t b) const;
};

// Steps (each in its own file).
void form_ribs(SweepState& s);
void make_charts(SweepState& s);
void make_pieces(SweepState& s);
void imprint_barrels(SweepState& s);
void mesh_stacks(SweepState& s);
void smooth_ends(SweepState& s);
void sweep_barrels(SweepState& s, std::vector<BarrelReport>* reports);
/// Before barrel b is swept: the images of its source cap's seam become the
/// nodes of its swept target's seam (weld_seams.cpp).
void weld_seam_images(SweepState& s, size_t b, const NodeImage& below);
/// After: no seam of a swept cap is left with unused nodes.
void check_seams_welded(SweepState& s);

}  // namespace cooperage::cooper::detail
