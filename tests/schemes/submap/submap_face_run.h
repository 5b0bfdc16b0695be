// Test helper: build a model with the OCC workbench, assign intervals with
// the submap constraints (cooperage::intervals::solve), mesh the curves
// (pipeline::mesh_curves) and one surface with submap; independent checks.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <utility>

#include "framework/geometry/model.h"
#include "framework/intervals/solve.h"
#include "framework/io/job.h"
#include "framework/mesh/mesh_db.h"
#include "framework/pipeline/mesh_curves.h"
#include "framework/scheme/scheme.h"

namespace cooperage::submap::test {

using geom::Vec3;

/// The surface of `model` whose bounding box is flat in z at height z (a
/// prism cap); 0 when there is none.
inline int cap_at(const geom::Model& model, double z) {
  for (const auto& s : model.surfaces()) {
    if (std::abs(s.box.min.z() - z) < 1e-7 && std::abs(s.box.max.z() - z) < 1e-7) return s.id;
  }
  return 0;
}

/// First surface satisfying pred; 0 when none.
inline int find_surface(const geom::Model& model,
                        const std::function<bool(const geom::Surface&)>& pred) {
  for (const auto& s : model.surfaces()) {
    if (pred(s)) return s.id;
  }
  return 0;
}

/// Curves of a surface's loops.
inline std::set<int> curves_of(const geom::Model& model, int surface_id) {
  std::set<int> out;
  for (const auto& loop : model.surface(surface_id).loops) {
    for (const auto& use : loop.uses) out.insert(use.curve);
  }
  return out;
}

struct FaceRun {
  intervals::IntervalProblem problem;
  intervals::IntervalSolution solution;
  mesh::MeshDB db;
  scheme::EntityMesh mesh;
};

/// Every curve of the model gets goal length / size; the scheme adds its
/// constraints for `surface_id`; solve, mesh curves, mesh the surface.
inline FaceRun run_face(const geom::Model& model, int surface_id,
                        const scheme::SurfaceScheme& scheme, double size,
                        const scheme::Settings* settings = nullptr) {
  FaceRun run;
  for (const auto& c : model.curves()) run.problem.add_curve(c.id, std::max(c.length / size, 1e-3));
  const scheme::SurfaceView view{model, surface_id, nullptr, settings};
  scheme.constrain(view, run.problem);
  run.solution = intervals::solve(run.problem);
  pipeline::mesh_curves(model, run.solution.intervals, io::MeshSettings{}, run.db);
  const scheme::SurfaceView meshed{model, surface_id, &run.db, settings};
  scheme::Settings params = settings ? *settings : scheme::Settings{};
  params.size = size;
  run.mesh = scheme.mesh(meshed, params);
  return run;
}

/// Left side minus right side of a linear constraint at the solution.
inline bool satisfied(const intervals::Constraint& c, const std::map<int, int>& x) {
  long sum = 0;
  for (const auto& t : c.terms) sum += static_cast<long>(t.coeff) * x.at(t.curve_id);
  if (c.kind == intervals::Constraint::Kind::Even) return sum % 2 == 0;
  switch (c.sense) {
    case intervals::Sense::Equal: return sum == c.rhs;
    case intervals::Sense::LessEqual: return sum <= c.rhs;
    case intervals::Sense::GreaterEqual: return sum >= c.rhs;
  }
  return false;
}

/// Minimum over quads and corners of the sine of the corner angle between
/// unit edges, signed by the surface normal at the corner.
inline double min_scaled_jacobian(const geom::Surface& surface, const scheme::EntityMesh& m) {
  double q = 2.0;
  for (const auto& quad : m.quads) {
    for (size_t k = 0; k < 4; ++k) {
      const Vec3& p = m.coords[static_cast<size_t>(quad[k])];
      const Vec3 a = (m.coords[static_cast<size_t>(quad[(k + 1) % 4])] - p).normalized();
      const Vec3 b = (m.coords[static_cast<size_t>(quad[(k + 3) % 4])] - p).normalized();
      const Vec3 n = surface.geometry->project(p).normal;
      q = std::min(q, a.cross(b).dot(n));
    }
  }
  return q;
}

/// Structural checks: boundary nodes are exactly the surface's curve nodes,
/// every quad is oriented with the natural normal, edges used once are
/// exactly the curve segments, others twice, nodes lie on the surface.
inline void expect_valid_surface_mesh(const geom::Model& model, int surface_id,
                                      const FaceRun& run) {
  const geom::Surface& surface = model.surface(surface_id);
  const scheme::EntityMesh& m = run.mesh;
  // Curve segments bound the mesh once, except on a seam (a curve used
  // twice by the surface's loops), which lies inside it.
  std::map<int, int> uses;
  for (const auto& loop : surface.loops) {
    for (const auto& use : loop.uses) ++uses[use.curve];
  }
  std::set<int> curve_nodes;
  std::set<std::pair<int, int>> curve_edges, seam_edges;
  for (const auto& [c, count] : uses) {
    const auto& chain = run.db.curve_nodes(c);
    for (size_t k = 0; k < chain.size(); ++k) {
      curve_nodes.insert(chain[k]);
      if (k + 1 < chain.size()) {
        const std::pair<int, int> e{std::min(chain[k], chain[k + 1]),
                                    std::max(chain[k], chain[k + 1])};
        (count == 1 ? curve_edges : seam_edges).insert(e);
      }
    }
  }
  std::set<int> global;
  for (int g : m.global) {
    if (g >= 0) {
      EXPECT_TRUE(global.insert(g).second) << "global node " << g << " appears twice";
    }
  }
  EXPECT_EQ(global, curve_nodes);
  auto gid = [&](int local) {
    const int g = m.global[static_cast<size_t>(local)];
    return g >= 0 ? g : -1 - local;  // new nodes get negative ids
  };
  std::map<std::pair<int, int>, int> edge_use;
  for (const auto& quad : m.quads) {
    std::array<Vec3, 4> p;
    for (size_t k = 0; k < 4; ++k) p[k] = m.coords[static_cast<size_t>(quad[k])];
    const Vec3 centre = 0.25 * (p[0] + p[1] + p[2] + p[3]);
    const Vec3 n = surface.geometry->project(centre).normal;
    EXPECT_GT((p[2] - p[0]).cross(p[3] - p[1]).dot(n), 0.0) << "quad against the natural normal";
    for (size_t k = 0; k < 4; ++k) {
      const int a = gid(quad[k]), b = gid(quad[(k + 1) % 4]);
      ++edge_use[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::set<std::pair<int, int>> once;
  for (const auto& [e, count] : edge_use) {
    EXPECT_LE(count, 2);
    if (count == 1) once.insert(e);
    if (seam_edges.count(e)) {
      EXPECT_EQ(count, 2) << "seam edge";
    }
  }
  EXPECT_EQ(once, curve_edges);
  for (const auto& x : m.coords) {
    EXPECT_LT(surface.geometry->project(x).distance, 1e-6 * (1.0 + model.box().diagonal()));
  }
  EXPECT_GT(min_scaled_jacobian(surface, m), 0.0) << "inverted quad";
}

}  // namespace cooperage::submap::test
