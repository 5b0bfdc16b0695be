#include "schemes/submap/submap_scheme.h"

#include "schemes/submap/facing_edges.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <cmath>
#include <unordered_map>

#include "framework/core/error.h"
#include "framework/core/text.h"
#include "framework/mesh/corner_untangle.h"
#include "schemes/submap/directions.h"
#include "schemes/submap/hole_offsets.h"
#include "schemes/submap/lattice.h"
#include "schemes/submap/submap_plan.h"
#include "schemes/submap/untangle.h"
#include "schemes/submap/uv_chart.h"

namespace cooperage::submap {
namespace {

[[noreturn]] void fail(int surface_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(surface_id), message);
}

// Boundary nodes of one loop in walk order (each use's chain without its
// last node), with their lattice points and continuous surface parameters.
struct LoopNodes {
  std::vector<BoundaryPoint> points;
  LatticePoint closure{0, 0};
};

// A curve of the face whose node steps differ by more than `ratio`: graded
// on purpose (a rib leaving a tangent cap, sizes near a small feature, a
// sweep's wall with its nodes on the levels of its caps).
bool has_graded_curve(const mesh::MeshDB& db, const SubmapPlan& plan, double ratio) {
  for (const LoopPlan& lp : plan.loops) {
    for (const auto& use : lp.uses) {
      if (!db.curve_meshed(use.curve)) continue;
      const std::vector<int>& chain = db.curve_nodes(use.curve);
      double shortest = std::numeric_limits<double>::infinity(), longest = 0.0;
      for (size_t k = 1; k < chain.size(); ++k) {
        const double d = (db.node(chain[k]) - db.node(chain[k - 1])).norm();
        shortest = std::min(shortest, d);
        longest = std::max(longest, d);
      }
      if (chain.size() > 2 && longest > ratio * shortest) return true;
    }
  }
  return false;
}

LoopNodes walk_nodes(const mesh::MeshDB& db, int sid, size_t loop_index, const LoopPlan& lp,
                     const UvChart& chart) {
  LoopNodes out;
  std::vector<int> nodes, counts;
  int previous_last = -1;
  for (size_t u = 0; u < lp.uses.size(); ++u) {
    const int curve = lp.uses[u].curve;
    if (!db.curve_meshed(curve)) fail(sid, "curve " + std::to_string(curve) + " is not meshed");
    std::vector<int> chain = db.curve_nodes(curve);
    if (chain.size() < 2) fail(sid, "curve " + std::to_string(curve) + " has no intervals");
    if (lp.uses[u].sense == geom::Sense::Reversed) std::reverse(chain.begin(), chain.end());
    if (previous_last >= 0 && chain.front() != previous_last) {
      fail(sid, "curve " + std::to_string(curve) + " does not continue the node chain of loop " +
                    std::to_string(loop_index));
    }
    previous_last = chain.back();
    nodes.insert(nodes.end(), chain.begin(), chain.end() - 1);
    counts.push_back(static_cast<int>(chain.size()) - 1);
  }
  if (!nodes.empty() && previous_last != nodes.front()) {
    fail(sid, "loop " + std::to_string(loop_index) + " does not close in the curve mesh");
  }
  const auto ij = walk_loop(lp.directions, counts, {0, 0}, &out.closure);
  Vec2 prev = Vec2::Zero();
  for (size_t k = 0; k < nodes.size(); ++k) {
    const Vec3& x = db.node(nodes[k]);
    prev = k == 0 ? chart.uv(x) : chart.uv_near(x, prev);
    out.points.push_back({ij[k], nodes[k], prev});
  }
  return out;
}

// Least-squares affine map from surface parameters to lattice coordinates,
// fitted on the outer loop; used to place holes. The parameters are taken
// relative to their mean (`origin`), so a far-away parameter origin (a
// translated model) costs no precision. An affine fit's predictions do not
// depend on an affine change of the parameters, so neither the kernel's
// choice of a plane's frame nor its origin changes where a hole goes.
struct UvToLattice {
  Vec2 origin = Vec2::Zero();
  Eigen::Matrix<double, 3, 2> map = Eigen::Matrix<double, 3, 2>::Zero();

  Eigen::Vector2d operator()(const Vec2& uv) const {
    const Vec2 d = uv - origin;
    const Eigen::RowVector3d row(d.x(), d.y(), 1.0);
    return (row * map).transpose();
  }
};

UvToLattice fit_uv_to_lattice(const std::vector<BoundaryPoint>& pts) {
  UvToLattice fit;
  for (const auto& b : pts) fit.origin += b.uv;
  fit.origin /= static_cast<double>(pts.size());
  Eigen::MatrixXd A(static_cast<Eigen::Index>(pts.size()), 3);
  Eigen::MatrixXd B(static_cast<Eigen::Index>(pts.size()), 2);
  for (size_t k = 0; k < pts.size(); ++k) {
    const auto r = static_cast<Eigen::Index>(k);
    const Vec2 d = pts[k].uv - fit.origin;
    A(r, 0) = d.x();
    A(r, 1) = d.y();
    A(r, 2) = 1.0;
    B(r, 0) = pts[k].ij[0];
    B(r, 1) = pts[k].ij[1];
  }
  fit.map = A.colPivHouseholderQr().solve(B);
  return fit;
}

std::string balance_text(const std::vector<BoundaryPoint>& pts, const LatticePoint& closure) {
  return "its intervals do not balance (the lattice walk ends " +
         std::to_string(closure[0] - pts.front().ij[0]) + ", " +
         std::to_string(closure[1] - pts.front().ij[1]) + " away from its start)";
}

}  // namespace

std::shared_ptr<const SubmapPlanData> SurfaceSubmap::plan(const scheme::SurfaceView& view) const {
  if (const auto* carried = scheme::carried_plan<SubmapPlanData>(view);
      carried && carried->surface_id == view.surface_id) {
    return {std::shared_ptr<const SubmapPlanData>(), carried};  // not owned: the caller keeps it
  }
  auto p = std::make_shared<SubmapPlanData>();
  p->surface_id = view.surface_id;
  p->plan =
      plan_submap(view.model, view.surface_id, view.settings().vertex_types(), options_.classify);
  return p;
}

scheme::Applicability SurfaceSubmap::applicable(const scheme::SurfaceView& view) const {
  std::shared_ptr<const SubmapPlanData> p = plan(view);
  const SubmapPlan& plan = p->plan;
  if (!plan.ok) return scheme::Applicability::no(plan.why, nullptr);
  return scheme::Applicability::yes(plan.score, plan.why, std::move(p));
}

void SurfaceSubmap::constrain(const scheme::SurfaceView& view,
                              intervals::IntervalProblem& problem) const {
  const auto carried = plan(view);
  add_submap_constraints(view.surface_id, carried->plan, problem);
  if (carried->plan.ok) {
    add_facing_edge_constraints(view.model, view.surface_id, carried->plan.loops.front(), problem);
  }
}

scheme::EntityMesh SurfaceSubmap::mesh(const scheme::SurfaceView& view,
                                       const scheme::Settings& params) const {
  const int sid = view.surface_id;
  if (!view.mesh) fail(sid, "submap needs the meshed curves");
  const mesh::MeshDB& db = *view.mesh;
  const std::shared_ptr<const SubmapPlanData> planned = plan(view);
  const SubmapPlan& plan = planned->plan;
  if (!plan.ok) fail(sid, "not submappable: " + plan.why);
  const geom::SurfaceGeometry& geometry = *view.surface().geometry;
  const UvChart chart(geometry);

  // 1. Lattice coordinates of every boundary node by the cumulative walk.
  std::vector<LoopNodes> loops;
  for (size_t l = 0; l < plan.loops.size(); ++l) {
    loops.push_back(walk_nodes(db, sid, l, plan.loops[l], chart));
    const LoopNodes& ln = loops.back();
    if (ln.closure != ln.points.front().ij) {
      fail(sid, (l == 0 ? std::string("outer loop: ") : "hole loop " + std::to_string(l) + ": ") +
                    balance_text(ln.points, ln.closure));
    }
  }

  // 2. Holes: shift their parameters next to the outer loop's (periodic
  // surfaces), then place them at the integer offset nearest to where the
  // outer loop's affine uv -> (i, j) fit puts them, among the offsets that
  // give a valid lattice region.
  std::vector<std::vector<BoundaryPoint>> placed{loops.front().points};
  if (loops.size() > 1) {
    const auto& outer = loops.front().points;
    Vec2 lo = outer.front().uv, hi = outer.front().uv;
    LatticePoint bmin = outer.front().ij, bmax = outer.front().ij;
    for (const auto& b : outer) {
      lo = lo.cwiseMin(b.uv);
      hi = hi.cwiseMax(b.uv);
      for (int a = 0; a < 2; ++a) {
        bmin[static_cast<size_t>(a)] =
            std::min(bmin[static_cast<size_t>(a)], b.ij[static_cast<size_t>(a)]);
        bmax[static_cast<size_t>(a)] =
            std::max(bmax[static_cast<size_t>(a)], b.ij[static_cast<size_t>(a)]);
      }
    }
    const UvToLattice fit = fit_uv_to_lattice(outer);
    for (size_t l = 1; l < loops.size(); ++l) {
      std::vector<BoundaryPoint> hole = loops[l].points;
      const Vec2 shift = chart.shift_near(hole.front().uv, 0.5 * (lo + hi)) - hole.front().uv;
      Vec2 predicted = Vec2::Zero();
      LatticePoint hmin = hole.front().ij, hmax = hole.front().ij;
      for (auto& b : hole) {
        b.uv += shift;
        const Eigen::Vector2d ij = fit(b.uv);
        predicted += Vec2(ij(0) - b.ij[0], ij(1) - b.ij[1]);
        for (size_t a = 0; a < 2; ++a) {
          hmin[a] = std::min(hmin[a], b.ij[a]);
          hmax[a] = std::max(hmax[a], b.ij[a]);
        }
      }
      predicted /= static_cast<double>(hole.size());
      // Candidate offsets keep the hole strictly inside the outer lattice
      // box; ties in distance (a half-integer prediction) go by the offsets,
      // never by noise (hole_offsets.h).
      const std::vector<LatticePoint> candidates =
          rank_hole_offsets(predicted, {bmin[0] + 1 - hmin[0], bmin[1] + 1 - hmin[1]},
                            {bmax[0] - 1 - hmax[0], bmax[1] - 1 - hmax[1]});
      constexpr size_t kMaxTries = 64;
      bool done = false;
      for (size_t c = 0; c < candidates.size() && c < kMaxTries && !done; ++c) {
        std::vector<BoundaryPoint> moved = hole;
        for (auto& b : moved) {
          b.ij[0] += candidates[c][0];
          b.ij[1] += candidates[c][1];
        }
        placed.push_back(moved);
        if (fill_lattice(placed).ok) {
          done = true;
        } else {
          placed.pop_back();
        }
      }
      if (!done) {
        fail(sid, "hole loop " + std::to_string(l) +
                      " does not fit inside the outer loop's lattice with these intervals");
      }
    }
  }

  // 3. Fill the lattice in surface parameters.
  for (const FillInterior mode : {FillInterior::Blend, FillInterior::Blocks}) {
    const LatticeFill fill = fill_lattice(placed, mode);
    if (!fill.ok) fail(sid, "the submap lattice is not a valid region: " + fill.why);

    // 4. Nodes: boundary points are the curve nodes (once, even at seams);
    // interior points go onto the surface.
    scheme::EntityMesh out;
    std::vector<Vec3> normals;
    std::vector<Vec2> node_uv;  // where each node's projections start (a B-spline's Newton)
    std::vector<bool> fixed;
    std::unordered_map<int, int> local_of_global;
    std::vector<int> local_of_point(fill.ij.size(), -1);
    for (size_t p = 0; p < fill.ij.size(); ++p) {
      const int g = fill.node[p];
      if (g >= 0) {
        auto it = local_of_global.find(g);
        if (it != local_of_global.end()) {
          local_of_point[p] = it->second;
          continue;
        }
        const int local = out.add(db.node(g), g);
        local_of_global.emplace(g, local);
        local_of_point[p] = local;
        const geom::SurfaceProjection pr = geometry.project_near(db.node(g), fill.uv[p]);
        normals.push_back(pr.normal);
        node_uv.push_back(pr.uv);
        fixed.push_back(true);
      } else {
        const geom::SurfaceProjection pr =
            geometry.project_near(geometry.point(fill.uv[p]), fill.uv[p]);
        local_of_point[p] = out.add(pr.point);
        normals.push_back(pr.normal);
        node_uv.push_back(pr.uv);
        fixed.push_back(false);
      }
    }
    out.quads.reserve(fill.cells.size());
    for (const auto& c : fill.cells) {
      out.quads.push_back(
          {local_of_point[static_cast<size_t>(c[0])], local_of_point[static_cast<size_t>(c[1])],
           local_of_point[static_cast<size_t>(c[2])], local_of_point[static_cast<size_t>(c[3])]});
    }

    // 5. Guarded smoothing, then the inversion check: never silent. The fill
    // carries a graded curve's spacing across the face (transfinite
    // interpolation along rows and columns); smoothing would only even it out
    // again (a rib leaving a tangent cap: cooper's tangent_grading.h; a side
    // of several barrels whose rows lie on the caps' levels, cooper's
    // level_spacing.h: evened out, a row moved 1 mm off the level of a blind
    // hole's floor, and the cap stacks folded). A single block (the lattice
    // fills its box) keeps a grading above half, or above 2 % on a face
    // where a volume scheme placed nodes along a curve; other lattices keep a
    // grading above half only on such a face (their fill is less even than
    // one block's, and smoothing mends it: gmsh_Angled
    // --dim 2, surface 30, min scaled Jacobian 0.22 unsmoothed, 0.33 smoothed).
    const bool block = fills_its_box(fill);
    const bool volume_placed =
        std::any_of(plan.loops.begin(), plan.loops.end(), [&](const LoopPlan& lp) {
          return std::any_of(lp.uses.begin(), lp.uses.end(),
                             [&](const auto& use) { return db.curve_placed_by_volume(use.curve); });
        });
    const bool keep = block ? has_graded_curve(db, plan, volume_placed ? 1.02 : 1.5)
                            : volume_placed && has_graded_curve(db, plan, 1.5);
    const Projector project = [&](const Vec3& x, size_t node) {
      const geom::SurfaceProjection pr = geometry.project_near(x, node_uv[node]);
      node_uv[node] = pr.uv;
      return pr;
    };
    if (!keep) smooth_quads(out.coords, normals, fixed, out.quads, project, options_.smooth);
    int inverted = -1;
    for (size_t q = 0; q < out.quads.size(); ++q) {
      if (quad_scaled_jacobian(out.coords, normals, out.quads[q]) <= 0.0) {
        inverted = static_cast<int>(q);
        break;
      }
    }
    if (inverted < 0) return out;
    // A blend across a reentrant corner can fold where the rows on its two
    // sides are spaced differently (a hole's wall notched down into a foot:
    // the notch's columns spread their rows over the notch's whole depth);
    // the same lattice cut into blocks at its corners fills each block alone.
    // Only where no other scheme may mesh the face (a sweep's side): where
    // the fallbacks may, pave's mesh is better (gmsh_Angled --dim 2 at D/80,
    // surface 28: blocks 0.36, pave 0.75).
    const bool no_other = !params.allow_fallback && !params.allow_quad_fallback;
    if (mode == FillInterior::Blocks || block || !no_other) {
      // Last, on a sweep's side: the nodes around the fold move, the rest
      // stays (untangle.h; a lug's cone on its wall, plan => mesh campaign
      // seed 7 case 33). Where no node alone can mend its worst quad, the
      // corners' areas are untangled first and the quads improved again
      // (corner_untangle.h; a lug's cone over a graded edge, seed 11 case 66).
      if (no_other && untangle_quads(out.coords, normals, fixed, out.quads, project) > 0.0)
        return out;
      if (no_other) {
        // The quads' untangling after it decides: it may lift the few
        // corners left tangled.
        mesh::untangle_corners(out.coords, normals, fixed, out.quads, project);
        if (untangle_quads(out.coords, normals, fixed, out.quads, project) > 0.0) return out;
      }
      // Where the fold was, for a person (the quad's index means nothing).
      Vec3 at = Vec3::Zero();
      for (int n : out.quads[static_cast<size_t>(inverted)])
        at += out.coords[static_cast<size_t>(n)] / 4.0;
      fail(sid, "the lattice fill gives an inverted quad at " + point_text(at.x(), at.y(), at.z()) +
                    "; the interval counts do not fit the face's shape");
    }
  }
  throw std::logic_error("submap: unreachable");
}

std::unique_ptr<scheme::SurfaceScheme> make_submap(SubmapOptions options) {
  return std::make_unique<SurfaceSubmap>(options);
}

}  // namespace cooperage::submap
