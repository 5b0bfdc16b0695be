#include "schemes/pave/pave_scheme.h"

#include "framework/core/error.h"
#include "framework/core/text.h"
#include "framework/quality/quad_metrics.h"
#include "framework/mesh/loop_nodes.h"
#include "framework/mesh2d/surface_chart.h"
#include "framework/scheme/vertex_angles.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <unordered_map>

namespace cooperage::pave {
namespace {

[[noreturn]] void fail(int surface_id, ErrorCode code, const std::string& message) {
  throw MeshingError(code, EntityRef::surface(surface_id), "pave: " + message);
}

using mesh::loop_curve_list;

/// The fewest intervals loop `l` of a surface needs. A loop of 4 nodes is
/// one quad, good only when its 4 nodes are the loop's 4 corners (4 curves
/// meeting at angles of 45-135 degrees); any other loop needs 6 (a triangle
/// face: 3 quads around its centre; a disk: a hexagon of 3 quads), and an
/// outer loop around holes too (its every-other-node polygon must not fold).
int fewest_intervals(const geom::Model& model, int surface_id, size_t l) {
  const geom::Surface& s = model.surface(surface_id);
  if (l == 0 && s.loops.size() > 1) return 6;
  if (s.loops[l].uses.size() != 4) return 6;
  for (const auto& corner : scheme::loop_corners(model, surface_id, static_cast<int>(l))) {
    if (corner.angle < 45.0 || corner.angle > 135.0) return 6;
  }
  return 4;
}

}  // namespace

scheme::Applicability PaveScheme::applicable(const scheme::SurfaceView& view) const {
  const geom::Surface& s = view.surface();
  const std::string name = "surface " + std::to_string(view.surface_id);
  if (s.loops.empty())
    return scheme::Applicability::no(name + ": no boundary loop, pave needs one");
  for (size_t l = 0; l < s.loops.size(); ++l) {
    if (s.loops[l].uses.empty()) {
      return scheme::Applicability::no(name + ": loop " + std::to_string(l) + " has no curves");
    }
  }
  // With the curves meshed (view.mesh), the interval counts are known: an
  // odd total has no all-quad mesh. At planning time they are not, and
  // constrain() makes the total even.
  if (view.mesh != nullptr) {
    size_t total = 0;
    bool all_meshed = true;
    for (const auto& loop : s.loops) {
      for (const auto& use : loop.uses) {
        if (!view.mesh->curve_meshed(use.curve)) {
          all_meshed = false;
          continue;
        }
        total += view.mesh->curve_nodes(use.curve).size() - 1;  // intervals
      }
    }
    if (all_meshed && total % 2 != 0) {
      return scheme::Applicability::no(name + ": the boundary has an odd number of intervals (" +
                                       std::to_string(total) + "), so no all-quad mesh exists");
    }
  }
  // A general fallback. The score is on the structured schemes' scale (the
  // scaled Jacobian they can reach at their worst vertex): pave's worst
  // element is typically 0.56-0.79 on the benchmark faces, so a map or submap
  // face with a corner squashed below ~0.6 goes to pave instead.
  return scheme::Applicability::yes(
      0.6, name + ": pave meshes any face (" + std::to_string(s.loops.size()) + " loop" +
               (s.loops.size() > 1 ? "s" : "") + ") given an even boundary interval count");
}

void PaveScheme::constrain(const scheme::SurfaceView& view,
                           intervals::IntervalProblem& problem) const {
  const geom::Surface& s = view.surface();
  const std::string name = "surface " + std::to_string(view.surface_id) + " (pave)";
  std::vector<int> all;
  std::string all_text;
  for (size_t l = 0; l < s.loops.size(); ++l) {
    std::vector<int> ids;
    for (const auto& use : s.loops[l].uses) ids.push_back(use.curve);  // a seam counts twice
    if (ids.empty()) continue;
    all.insert(all.end(), ids.begin(), ids.end());
    all_text += (all_text.empty() ? "" : "+") + loop_curve_list(s.loops[l]);
    const int least = fewest_intervals(view.model, view.surface_id, l);
    problem.add_at_least(ids, least,
                         name + ": loop " + std::to_string(l) + " curves " +
                             loop_curve_list(s.loops[l]) + " >= " + std::to_string(least));
  }
  if (!all.empty()) problem.add_even(all, name + ": boundary curves " + all_text + " even");
}

scheme::EntityMesh PaveScheme::mesh(const scheme::SurfaceView& view,
                                    const scheme::Settings& /*params*/) const {
  const int sid = view.surface_id;
  if (!view.mesh) fail(sid, ErrorCode::Internal, "mesh() needs the meshed curves");
  const mesh::MeshDB& db = *view.mesh;
  const geom::Surface& surface = view.surface();
  if (surface.loops.empty()) fail(sid, ErrorCode::NotApplicable, "no boundary loop");
  if (!surface.geometry) fail(sid, ErrorCode::Internal, "no surface geometry");

  const std::vector<std::vector<int>> rings = mesh::surface_loop_nodes(view.model, sid, db);
  size_t total = 0;
  for (const auto& ring : rings) total += ring.size();
  if (total % 2 != 0) {
    fail(sid, ErrorCode::InvalidInput,
         "the boundary has an odd number of intervals (" + std::to_string(total) +
             "), so no all-quad mesh exists; pave's interval constraints (constrain()) "
             "require an even total");
  }
  for (size_t l = 0; l < rings.size(); ++l) {
    if (rings[l].size() < 4) {
      fail(sid, ErrorCode::InvalidInput,
           "loop " + std::to_string(l) + " (curves " + loop_curve_list(surface.loops[l]) +
               ") has " + std::to_string(rings[l].size()) +
               " intervals; pave needs at least 4 per loop");
    }
  }

  std::vector<std::vector<geom::Vec3>> loops3d;
  for (const auto& ring : rings) {
    std::vector<geom::Vec3> l;
    for (int g : ring) l.push_back(db.node(g));
    loops3d.push_back(std::move(l));
  }
  const geom::SurfaceGeometry& geometry = *surface.geometry;
  std::unique_ptr<mesh2d::SurfaceChart> chart;
  QuadMesh2D m;
  try {
    chart = std::make_unique<mesh2d::SurfaceChart>(geometry, loops3d);
    m = pave_2d(chart->loops_2d(), options_);
  } catch (const MeshingError& e) {
    fail(sid, e.code(), e.message());
  }
  const mesh2d::SurfaceChart& map = *chart;

  scheme::EntityMesh out;
  std::vector<int> local(m.points.size(), -1);
  std::unordered_map<int, int> local_of_global;  // seams: a node used twice in a ring is one node
  size_t i = 0;
  for (const auto& loop : map.sources()) {  // chart points: loop nodes (touching loops merged)
    for (const mesh2d::LoopPointRef& r : loop) {
      const int g = rings[static_cast<size_t>(r.loop)][static_cast<size_t>(r.index)];
      auto it = local_of_global.find(g);
      if (it == local_of_global.end())
        it = local_of_global.emplace(g, out.add(db.node(g), g)).first;
      local[i++] = it->second;
    }
  }
  for (; i < m.points.size(); ++i) local[i] = out.add(map.to_3d(m.points[i]));

  out.quads.reserve(m.quads.size());
  int negative = 0;
  std::vector<geom::Vec3> normals;
  normals.reserve(m.quads.size());
  for (const auto& q : m.quads) {
    mesh::Quad quad{local[static_cast<size_t>(q[0])], local[static_cast<size_t>(q[1])],
                    local[static_cast<size_t>(q[2])], local[static_cast<size_t>(q[3])]};
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        if (quad[static_cast<size_t>(a)] == quad[static_cast<size_t>(b)]) {
          fail(sid, ErrorCode::MeshingFailed,
               "a quad uses one node twice (too few intervals across a seam)");
        }
      }
    }
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (int v : q) c += m.points[static_cast<size_t>(v)];
    const geom::Vec3 n = map.normal_at(c / 4.0);
    const geom::Vec3 d =
        (out.coords[static_cast<size_t>(quad[2])] - out.coords[static_cast<size_t>(quad[0])])
            .cross(out.coords[static_cast<size_t>(quad[3])] -
                   out.coords[static_cast<size_t>(quad[1])]);
    if (d.dot(n) < 0) ++negative;
    normals.push_back(n);
    out.quads.push_back(quad);
  }
  if (2 * negative > static_cast<int>(out.quads.size())) {
    for (auto& q : out.quads) std::swap(q[1], q[3]);
  }
  for (size_t k = 0; k < out.quads.size(); ++k) {
    const auto& q = out.quads[k];
    const quality::QuadNodes p{
        out.coords[static_cast<size_t>(q[0])], out.coords[static_cast<size_t>(q[1])],
        out.coords[static_cast<size_t>(q[2])], out.coords[static_cast<size_t>(q[3])]};
    if (!(quality::quad_scaled_jacobian(p, normals[k]) > 0)) {
      const Eigen::Vector3d at = (p[0] + p[1] + p[2] + p[3]) / 4.0;
      fail(sid, ErrorCode::MeshingFailed,
           "a quad at " + point_text(at.x(), at.y(), at.z()) +
               " is inverted on the surface (distortion of the parameter space)");
    }
  }
  return out;
}

std::unique_ptr<scheme::SurfaceScheme> make_pave() { return std::make_unique<PaveScheme>(); }

}  // namespace cooperage::pave
