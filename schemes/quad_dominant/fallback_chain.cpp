#include "schemes/quad_dominant/fallback_chain.h"

#include "framework/core/error.h"
#include "framework/geometry/evaluators.h"
#include "framework/geometry/projection_walk.h"
#include "framework/mesh/corner_sine.h"
#include "framework/mesh/improve_split_nodes.h"
#include "framework/mesh/loop_nodes.h"
#include "framework/mesh/strip_elements.h"
#include "framework/scheme/vertex_angles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>

namespace cooperage::quad_dominant {
namespace {

using geom::Vec3;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

/// One candidate mesh and its worst element.
struct Candidate {
  std::string what;  ///< "pave's all-quad mesh", ...
  scheme::EntityMesh mesh;
  mesh::SurfaceMeshQuality quality;
};

// Rungs of a strip's row at most this many mean boundary edges long.
constexpr double kStripWidth = 3.0;

// A face of one loop between two tips (its sharpest corner below 90
// degrees, the next below 180) and thinner than its elements, as one row of
// elements (strip_elements.h); nullopt for any other face.
std::optional<scheme::EntityMesh> strip_mesh(const scheme::SurfaceView& view) {
  const geom::Surface& s = view.surface();
  if (!view.mesh || s.loops.size() != 1) return std::nullopt;
  std::vector<scheme::LoopCorner> corners = scheme::loop_corners(view.model, view.surface_id, 0);
  if (corners.size() < 2) return std::nullopt;
  std::stable_sort(corners.begin(), corners.end(),
                   [](const auto& x, const auto& y) { return x.angle < y.angle; });
  if (corners[0].angle >= 90.0 || corners[1].angle >= 180.0) return std::nullopt;
  const std::vector<int> ring =
      mesh::surface_loop_nodes(view.model, view.surface_id, *view.mesh)[0];
  std::vector<size_t> tips;
  for (size_t c = 0; c < 2; ++c) {
    const int node = view.mesh->vertex_node(corners[c].vertex);
    size_t found = 0, at = 0;
    for (size_t k = 0; k < ring.size(); ++k) {
      if (ring[k] == node) {
        ++found;
        at = k;
      }
    }
    if (found != 1) return std::nullopt;  // a vertex the loop passes twice
    tips.push_back(at);
  }
  std::vector<Vec3> x;
  for (int node : ring) x.push_back(view.mesh->node(node));
  const auto elements =
      mesh::strip_elements(x, std::min(tips[0], tips[1]), std::max(tips[0], tips[1]));
  if (!elements) return std::nullopt;
  // Thinner than its elements: no rung of the row longer than kStripWidth
  // mean boundary edges (a wide face in one row would be far coarser than
  // its curves ask).
  const size_t n = x.size();
  double perimeter = 0, widest = 0;
  for (size_t k = 0; k < n; ++k) perimeter += (x[(k + 1) % n] - x[k]).norm();
  const auto rung = [&](int u, int v) {  // an element edge across the face
    const size_t a = static_cast<size_t>(u), b = static_cast<size_t>(v);
    if ((a + 1) % n != b && (b + 1) % n != a) widest = std::max(widest, (x[a] - x[b]).norm());
  };
  for (const mesh::Quad& q : elements->quads) {
    for (int k = 0; k < 4; ++k) rung(q[k], q[(k + 1) % 4]);
  }
  for (const mesh::Tri& t : elements->tris) {
    for (int k = 0; k < 3; ++k) rung(t[k], t[(k + 1) % 3]);
  }
  if (widest > kStripWidth * perimeter / static_cast<double>(n)) return std::nullopt;
  scheme::EntityMesh out;
  for (size_t k = 0; k < ring.size(); ++k) out.add(x[k], ring[k]);
  out.quads = elements->quads;
  out.tris = elements->tris;
  return out;
}

}  // namespace

double reachable_floor(double min_quality, double sharpest_degrees) {
  const double angle = std::max(sharpest_degrees, kSharpestCornerCounted);
  if (angle >= 90.0) return min_quality;
  return std::min(min_quality, 0.95 * std::sin(angle * M_PI / 180.0));
}

FallbackChain::FallbackChain(std::unique_ptr<scheme::SurfaceScheme> primary,
                             std::unique_ptr<scheme::SurfaceScheme> quads,
                             std::unique_ptr<scheme::SurfaceScheme> triangles, double min_quality)
    : primary_(std::move(primary)),
      quads_(std::move(quads)),
      triangles_(std::move(triangles)),
      min_quality_(min_quality) {}

scheme::EntityMesh FallbackChain::primary_or_quads(const scheme::SurfaceView& view,
                                                   const scheme::Settings& params) const {
  try {
    return primary_->mesh(view, params);
  } catch (const MeshingError& e) {
    // The primary's reason is the one to act on when the fallback fails too.
    const std::exception_ptr primary_error = std::current_exception();
    // view.plan is the primary's (its applicable()); the fallback plans anew.
    scheme::SurfaceView own = view;
    own.plan = nullptr;
    scheme::EntityMesh quads;
    try {
      quads = quads_->mesh(own, params);
    } catch (const MeshingError&) {
      std::rethrow_exception(primary_error);
    }
    if (const geom::SurfaceGeometry* surface = view.surface().geometry.get()) {
      geom::ProjectionWalk walk(*surface);
      const auto normal_at = [&walk](const Vec3& x, double reach) {
        return walk.project(x, reach).normal;
      };
      if (mesh::surface_mesh_quality(quads.coords, quads.quads, quads.tris, normal_at).inverted > 0)
        std::rethrow_exception(primary_error);
    }
    quads.warnings.push_back(std::string(primary_->name()) + " failed (" + e.message() + "); " +
                             std::string(quads_->name()) +
                             "'s all-quad mesh instead (the volumes take any quad mesh of it)");
    return quads;
  }
}

scheme::EntityMesh FallbackChain::mesh(const scheme::SurfaceView& view,
                                       const scheme::Settings& params) const {
  if (!params.allow_fallback) {
    if (params.allow_quad_fallback && quads_) return primary_or_quads(view, params);
    return primary_->mesh(view, params);
  }
  const geom::SurfaceGeometry* surface = view.surface().geometry.get();
  if (surface == nullptr) return primary_->mesh(view, params);
  // One walk for the whole chain: its meshes are scored one after another.
  geom::ProjectionWalk walk(*surface);
  const auto normal_at = [&walk](const Vec3& x, double reach) {
    return walk.project(x, reach).normal;
  };
  const std::string floor = number(min_quality_);
  // What the face allows: below it the chain looks further, at or above it
  // the first mesh is kept (a 3-degree corner is no reason to give up quads).
  const auto sharpest = scheme::sharpest_corner(view.model, view.surface_id);
  const double corner = sharpest ? sharpest->angle : 360.0;
  const double reachable = reachable_floor(min_quality_, corner);

  std::vector<std::string> given_up;  // why each step before the kept one was not kept
  std::optional<Candidate> best;      // the valid candidate with the best worst element
  std::optional<Candidate> best_quads;
  auto consider = [&](Candidate c) -> bool {
    const bool valid = c.quality.inverted == 0;
    if (!valid) {
      given_up.push_back(c.what + " has " + std::to_string(c.quality.inverted) +
                         " inverted elements");
      return false;
    }
    if (c.mesh.tris.empty() && (!best_quads || c.quality.min > best_quads->quality.min))
      best_quads = c;
    const bool good = c.quality.min >= reachable;
    if (!good)
      given_up.push_back(c.what + " reaches a scaled Jacobian of only " + number(c.quality.min));
    if (!best || c.quality.min > best->quality.min) best = std::move(c);
    return good;
  };
  auto run = [&](const scheme::SurfaceScheme& s, const std::string& what) -> bool {
    try {
      // view.plan is the primary's (its applicable()); a fallback plans anew.
      scheme::SurfaceView own = view;
      if (&s != primary_.get()) own.plan = nullptr;
      scheme::EntityMesh m = s.mesh(own, params);
      const mesh::SurfaceMeshQuality q =
          mesh::surface_mesh_quality(m.coords, m.quads, m.tris, normal_at);
      return consider({what, std::move(m), q});
    } catch (const MeshingError& e) {
      given_up.push_back(what + " failed (" + e.message() + ")");
      return false;
    }
  };
  auto finish = [&](bool fell_back) {
    scheme::EntityMesh out = std::move(best->mesh);
    if (fell_back) {
      std::string text;
      for (const std::string& g : given_up) text += (text.empty() ? "" : "; ") + g;
      std::string kept = best->what + " instead";
      if (!out.tris.empty()) {
        kept += " (" + std::to_string(out.quads.size()) + " quads, " +
                std::to_string(out.tris.size()) + " triangles)";
      }
      if (best->quality.min < min_quality_) {
        kept += "; no mesh reaches " + floor + ", the best has worst element " +
                number(best->quality.min);
        if (corner < 90.0 && std::sin(corner * M_PI / 180.0) < min_quality_ + 0.05) {
          kept += " (the face has a corner of " + number(corner) +
                  " degrees: no element at it can exceed sin of that angle)";
        }
      } else {
        kept += " (worst element " + number(best->quality.min) + ")";
      }
      out.warnings.push_back(std::string(primary_->name()) + ": " + text + "; " + kept);
    }
    return out;
  };

  // 1. The primary scheme; 2. the all-quad fallback.
  if (run(*primary_, std::string(primary_->name()) + "'s mesh")) {
    if (best->quality.min < min_quality_) {
      best->mesh.warnings.push_back(std::string(primary_->name()) + ": worst element " +
                                    number(best->quality.min) + ", below " + floor +
                                    ": the face has a corner of " + number(corner) +
                                    " degrees, and no element at it can exceed sin of that angle");
    }
    return finish(false);
  }
  if (quads_ && run(*quads_, std::string(quads_->name()) + "'s all-quad mesh")) return finish(true);
  // 3. Quad-dominant: the best quad mesh with its poor quads split.
  if (best_quads) {
    Candidate qd = *best_quads;
    std::vector<bool> movable(qd.mesh.coords.size());
    for (size_t i = 0; i < movable.size(); ++i) movable[i] = qd.mesh.global[i] < 0;
    const mesh::QuadDominant split = mesh::make_quad_dominant(
        qd.mesh.coords, qd.mesh.quads, movable,
        [surface](const Vec3& x) { return surface->project(x).point; }, min_quality_);
    qd.mesh.quads = split.quads;
    qd.mesh.tris = split.tris;
    qd.what = "a quad-dominant mesh (" + best_quads->what + ", quads below " + floor + " split)";
    qd.quality = mesh::surface_mesh_quality(qd.mesh.coords, qd.mesh.quads, qd.mesh.tris, normal_at);
    if (consider(std::move(qd))) return finish(true);
  }
  // 4. A strip between two tips: one row of quads, a triangle at each tip.
  try {
    if (auto strip = strip_mesh(view)) {
      const mesh::SurfaceMeshQuality q =
          mesh::surface_mesh_quality(strip->coords, strip->quads, strip->tris, normal_at);
      const std::string what = "one row of elements between its two tips";
      if (consider({what, std::move(*strip), q})) return finish(true);
    }
  } catch (const MeshingError& e) {
    given_up.push_back("one row of elements between its two tips failed (" + e.message() + ")");
  }
  // 5. Triangles.
  if (triangles_ && run(*triangles_, "a triangle mesh (" + std::string(triangles_->name()) + ")")) {
    return finish(true);
  }
  if (best) return finish(true);
  std::string text;
  for (const std::string& g : given_up) text += (text.empty() ? "" : "; ") + g;
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(view.surface_id),
                     "no valid mesh: " + text);
}

}  // namespace cooperage::quad_dominant
