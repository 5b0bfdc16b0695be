#include "framework/mesh2d/surface_chart.h"
#include "framework/mesh2d/polygon_area.h"

#include "framework/core/error.h"
#include "framework/mesh2d/conformal_map.h"
#include "framework/mesh2d/loop_parameters.h"
#include "framework/mesh2d/triangle_locator.h"
#include "framework/mesh2d/triangulate.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace cooperage::mesh2d {
namespace {

using Eigen::Vector2d;
using geom::Vec2;
using geom::Vec3;

[[noreturn]] void fail(const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, message);
}

double diagonal(const std::vector<std::vector<Vector2d>>& loops) {
  Eigen::AlignedBox2d box;
  for (const auto& l : loops) {
    for (const Vector2d& p : l) box.extend(p);
  }
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

/// Mean |dS/du| and |dS/dv| over the loops' points that are no pole.
Vec2 mean_metric(const geom::SurfaceGeometry& surface, const LoopParameters& lp) {
  const auto [u, v] = surface.uv_bounds();
  const double hu = 1e-5 * std::max(u.y() - u.x(), 1e-12);
  const double hv = 1e-5 * std::max(v.y() - v.x(), 1e-12);
  double su = 0.0, sv = 0.0;
  int count = 0;
  for (size_t l = 0; l < lp.uv.size(); ++l) {
    for (size_t k = 0; k < lp.uv[l].size(); ++k) {
      if (lp.pole[l][k]) continue;
      const Vec2& x = lp.uv[l][k];
      su += (surface.point(x + Vec2(hu, 0)) - surface.point(x - Vec2(hu, 0))).norm() / (2 * hu);
      sv += (surface.point(x + Vec2(0, hv)) - surface.point(x - Vec2(0, hv))).norm() / (2 * hv);
      ++count;
    }
  }
  Vec2 s(count > 0 ? su / count : 1.0, count > 0 ? sv / count : 1.0);
  if (!(s.x() > 0) || !std::isfinite(s.x())) s.x() = 1.0;
  if (!(s.y() > 0) || !std::isfinite(s.y())) s.y() = 1.0;
  return s;
}

}  // namespace

SurfaceChart::~SurfaceChart() = default;
SurfaceChart::SurfaceChart(SurfaceChart&&) noexcept = default;

SurfaceChart::SurfaceChart(const geom::SurfaceGeometry& surface,
                           const std::vector<std::vector<Vec3>>& loops, const ChartOptions& options)
    : surface_(surface) {
  if (loops.empty() || loops.front().size() < 2) fail("the face has no boundary loop to flatten");
  if (surface.type() == geom::SurfaceType::Plane) {
    make_plane(loops);
  } else {
    make_curved(loops, options);
  }
}

void SurfaceChart::make_curved(const std::vector<std::vector<Vec3>>& loops,
                               const ChartOptions& options) {
  const LoopParameters lp = loop_parameters(surface_, loops, 4);
  const Vec2 scale = mean_metric(surface_, lp);
  su_ = scale.x();
  sv_ = scale.y() * lp.orientation;
  std::vector<std::vector<Vector2d>> scaled(lp.uv.size());
  for (size_t l = 0; l < lp.uv.size(); ++l) {
    for (const Vec2& x : lp.uv[l]) scaled[l].emplace_back(x.x() * su_, x.y() * sv_);
  }
  if (signed_area(scaled.front()) < 0) {
    // The loops disagree with the normal: mirror (folded into sv_), the
    // scheme flips its elements.
    mirrored_ = true;
    sv_ = -sv_;
    for (auto& l : scaled) {
      for (auto& p : l) p.y() = -p.y();
    }
  }
  // Loops touching at a node: merged, copies apart. A point of `sep` is
  // polygon point (loop, index) of lp, i.e. loop node lp.node[loop][index].
  const SeparatedLoops sep = separate_touching_points(scaled, 1e-9 * diagonal(scaled));
  std::string why = invalid_loops(sep.loops);
  if (!why.empty())
    fail("the boundary is not a valid region in the face's parameter plane (" + why + ")");
  auto node_of = [&](const LoopPointRef& r) {
    return LoopPointRef{r.loop, lp.node[static_cast<size_t>(r.loop)][static_cast<size_t>(r.index)]};
  };
  auto is_pole = [&](const LoopPointRef& r) {
    return lp.pole[static_cast<size_t>(r.loop)][static_cast<size_t>(r.index)] != 0;
  };

  // Background triangulation of the scaled plane, placed on the surface.
  RefineOptions refine;
  refine.min_angle_deg = 25.0;
  refine.size_factor = 1.0;
  refine.size_scale = options.background_size;
  const Triangulation2D bg = triangulate(sep.loops, refine);
  auto uv_of = [&](const Vector2d& p) { return Vec2(p.x() / su_, p.y() / sv_); };
  std::vector<Vec3> xyz(bg.points.size());
  for (size_t i = 0; i < bg.points.size(); ++i) xyz[i] = surface_.point(uv_of(bg.points[i]));

  auto use_scaled_uv = [&]() {
    kind_ = Kind::ScaledUv;
    loops_2d_ = sep.loops;
    sources_.assign(sep.source.size(), {});
    for (size_t l = 0; l < sep.source.size(); ++l) {
      for (const LoopPointRef& r : sep.source[l]) sources_[l].push_back(node_of(r));
    }
  };
  if (!lp.has_poles() &&
      max_conformal_distortion(xyz, bg.points, bg.triangles) <= options.max_distortion) {
    use_scaled_uv();
    return;
  }

  // Conformal map of the background. A pole's points merge into one vertex.
  std::vector<int> merged(bg.points.size());
  for (size_t i = 0; i < merged.size(); ++i) merged[i] = static_cast<int>(i);
  std::vector<std::vector<int>> out_vertex(sep.loops.size());  // per chart point: its vertex
  std::map<std::pair<int, int>, int> pole_vertex;              // (loop, node) -> vertex
  size_t b = 0;
  for (size_t l = 0; l < sep.loops.size(); ++l) {
    for (size_t k = 0; k < sep.loops[l].size(); ++k, ++b) {
      const LoopPointRef r = sep.source[l][k];
      const LoopPointRef n = node_of(r);
      if (!is_pole(r)) {
        out_vertex[l].push_back(static_cast<int>(b));
        sources_.resize(sep.loops.size());
        sources_[l].push_back(n);
        continue;
      }
      xyz[b] = loops[static_cast<size_t>(n.loop)][static_cast<size_t>(n.index)];
      const auto [it, fresh] =
          pole_vertex.emplace(std::make_pair(n.loop, n.index), static_cast<int>(b));
      merged[b] = it->second;
      if (fresh) {
        out_vertex[l].push_back(static_cast<int>(b));
        sources_.resize(sep.loops.size());
        sources_[l].push_back(n);
      }
    }
  }
  sources_.resize(sep.loops.size());
  std::vector<std::array<int, 3>> tris;
  std::vector<std::array<Vec2, 3>> corner_uv;
  for (const auto& t : bg.triangles) {
    const std::array<int, 3> m{merged[static_cast<size_t>(t[0])], merged[static_cast<size_t>(t[1])],
                               merged[static_cast<size_t>(t[2])]};
    if (m[0] == m[1] || m[1] == m[2] || m[0] == m[2]) continue;  // collapsed at a pole
    tris.push_back(m);
    corner_uv.push_back({uv_of(bg.points[static_cast<size_t>(t[0])]),
                         uv_of(bg.points[static_cast<size_t>(t[1])]),
                         uv_of(bg.points[static_cast<size_t>(t[2])])});
  }
  // Pinned: the first chart point and the boundary vertex farthest from it.
  const int pin0 = out_vertex[0][0];
  int pin1 = -1;
  double far = -1.0;
  for (const auto& loop : out_vertex) {
    for (int v : loop) {
      const double d = (xyz[static_cast<size_t>(v)] - xyz[static_cast<size_t>(pin0)]).squaredNorm();
      if (v != pin0 && d > far) {
        far = d;
        pin1 = v;
      }
    }
  }
  if (pin1 < 0 || !(far > 0)) fail("the face's boundary has no extent");
  const std::vector<Vector2d> flat = conformal_map(xyz, tris, pin0, pin1);
  // The conformal map keeps angles but is not always one-to-one (thin slits
  // of a face may close up); then the scaled plane, valid though distorted,
  // is the chart when there is no pole.
  if (!std::isfinite(max_conformal_distortion(xyz, flat, tris))) {
    if (!lp.has_poles()) return use_scaled_uv();
    fail("the conformal map of the face folds over (a triangle is inverted)");
  }
  loops_2d_.assign(sep.loops.size(), {});
  for (size_t l = 0; l < out_vertex.size(); ++l) {
    for (int v : out_vertex[l]) loops_2d_[l].push_back(flat[static_cast<size_t>(v)]);
  }
  why = invalid_loops(loops_2d_);
  if (!why.empty()) {
    if (!lp.has_poles()) return use_scaled_uv();
    fail("the conformal map of the face gives an invalid boundary (" + why + ")");
  }
  kind_ = Kind::Conformal;
  corner_uv_ = std::move(corner_uv);
  locator_ = std::make_unique<TriangleLocator>(flat, std::move(tris));
}

void SurfaceChart::make_plane(const std::vector<std::vector<Vec3>>& loops) {
  kind_ = Kind::Plane;
  origin_ = loops[0][0];
  const Vec3 n = surface_.project(origin_).normal.normalized();
  Vec3 e = loops[0][1] - origin_;
  e -= e.dot(n) * n;
  if (!(e.norm() > 0)) fail("the first two boundary nodes coincide");
  ex_ = e.normalized();
  ey_ = n.cross(ex_);
  normal_ = n;
  for (const auto& loop : loops) {
    std::vector<Vector2d> l;
    for (const Vec3& p : loop) l.emplace_back((p - origin_).dot(ex_), (p - origin_).dot(ey_));
    loops_2d_.push_back(std::move(l));
  }
  if (signed_area(loops_2d_.front()) < 0) {
    // The loops disagree with the normal: mirror, the scheme flips its elements.
    mirrored_ = true;
    for (auto& l : loops_2d_) {
      for (auto& p : l) p.y() = -p.y();
    }
  }
  SeparatedLoops sep = separate_touching_points(loops_2d_, 1e-9 * diagonal(loops_2d_));
  loops_2d_ = std::move(sep.loops);
  sources_ = std::move(sep.source);
  const std::string why = invalid_loops(loops_2d_);
  if (!why.empty()) fail("the boundary is not a valid region in the face's plane (" + why + ")");
}

Vec2 SurfaceChart::uv_at(const Vector2d& x) const {
  switch (kind_) {
    case Kind::Plane: return surface_.project(to_3d(x)).uv;
    case Kind::ScaledUv: return Vec2(x.x() / su_, x.y() / sv_);
    case Kind::Conformal: {
      const TriangleLocator::Hit hit = locator_->locate(x);
      const auto& c = corner_uv_[static_cast<size_t>(hit.triangle)];
      return hit.weights[0] * c[0] + hit.weights[1] * c[1] + hit.weights[2] * c[2];
    }
  }
  return Vec2::Zero();
}

Vec3 SurfaceChart::to_3d(const Vector2d& xm) const {
  if (kind_ == Kind::Plane) {
    const Vector2d x(xm.x(), mirrored_ ? -xm.y() : xm.y());
    return origin_ + x.x() * ex_ + x.y() * ey_;
  }
  return surface_.point(uv_at(xm));
}

Vec3 SurfaceChart::normal_at(const Vector2d& x) const {
  if (kind_ == Kind::Plane) return normal_;
  return surface_.normal(uv_at(x));
}

std::string SurfaceChart::describe() const {
  switch (kind_) {
    case Kind::Plane: return "plane";
    case Kind::ScaledUv: return "scaled (u, v)";
    case Kind::Conformal: return "conformal map";
  }
  return {};
}

}  // namespace cooperage::mesh2d
