#include "schemes/tri/face_space.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace cooperage::tri {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

[[noreturn]] void fail(int surface_id, const std::string& message) {
  throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(surface_id), message);
}

// Periods of the (u, v) parameters (0: not periodic), by surface type
// (OpenCASCADE convention: u is the angle about the axis of revolution).
Vec2 periods(geom::SurfaceType type) {
  using geom::SurfaceType;
  switch (type) {
    case SurfaceType::Cylinder:
    case SurfaceType::Cone:
    case SurfaceType::Sphere:
    case SurfaceType::Revolution:
      return {kTwoPi, 0.0};
    case SurfaceType::Torus:
      return {kTwoPi, kTwoPi};
    default:
      return {0.0, 0.0};
  }
}

double unwrap(double value, double previous, double period) {
  if (period <= 0.0) return value;
  return value - period * std::round((value - previous) / period);
}

}  // namespace

std::vector<std::vector<int>> loop_nodes(const geom::Model& model, int surface_id,
                                         const mesh::MeshDB& db) {
  std::vector<std::vector<int>> out;
  for (const geom::Loop& loop : model.surface(surface_id).loops) {
    std::vector<int> ring;
    for (const geom::CurveUse& use : loop.uses) {
      if (!db.curve_meshed(use.curve)) {
        fail(surface_id, "curve " + std::to_string(use.curve) + " is not meshed");
      }
      std::vector<int> chain = db.curve_nodes(use.curve);
      if (chain.size() < 2)
        fail(surface_id, "curve " + std::to_string(use.curve) + " has no intervals");
      if (use.sense == geom::Sense::Reversed) std::reverse(chain.begin(), chain.end());
      if (!ring.empty() && ring.back() != chain.front()) {
        fail(surface_id, "curve " + std::to_string(use.curve) + " does not continue its loop");
      }
      ring.insert(ring.end(), chain.begin() + (ring.empty() ? 0 : 1), chain.end());
    }
    if (ring.size() < 2 || ring.front() != ring.back()) fail(surface_id, "a loop does not close");
    ring.pop_back();
    if (ring.size() < 3) fail(surface_id, "a loop has fewer than 3 intervals");
    out.push_back(std::move(ring));
  }
  return out;
}

FaceSpace::FaceSpace(const geom::Model& model, int surface_id, const mesh::MeshDB& db,
                     FlatFace& out)
    : surface_(&model.surface(surface_id)) {
  const geom::SurfaceGeometry& g = *surface_->geometry;
  out.nodes = loop_nodes(model, surface_id, db);
  out.loops.clear();
  planar_ = g.type() == geom::SurfaceType::Plane;
  const std::vector<int>& outer = out.nodes.front();
  if (planar_) {
    // Frame at the first boundary node, x along the first segment.
    origin_ = db.node(outer[0]);
    n_ = g.project(origin_).normal.normalized();
    ex_ = db.node(outer[1]) - origin_;
    ex_ -= n_ * n_.dot(ex_);
    if (!(ex_.norm() > 0.0)) fail(surface_id, "degenerate first boundary segment");
    ex_.normalize();
    ey_ = n_.cross(ex_);
    for (const auto& ring : out.nodes) {
      std::vector<Vec2> loop;
      for (int k : ring) loop.push_back(flat_planar(db.node(k)));
      out.loops.push_back(std::move(loop));
    }
    return;
  }
  // Curved: parameters of every boundary node, unwrapped along each loop.
  const Vec2 period = periods(g.type());
  std::vector<std::vector<Vec2>> uv;
  for (const auto& ring : out.nodes) {
    std::vector<Vec2> loop;
    for (int k : ring) {
      Vec2 p = g.project(db.node(k)).uv;
      if (!loop.empty()) {
        p.x() = unwrap(p.x(), loop.back().x(), period.x());
        p.y() = unwrap(p.y(), loop.back().y(), period.y());
      }
      loop.push_back(p);
    }
    // Back at the start: a loop that winds around a periodic direction has no seam.
    const Vec2 close(unwrap(loop.front().x(), loop.back().x(), period.x()),
                     unwrap(loop.front().y(), loop.back().y(), period.y()));
    if ((close - loop.front()).norm() > 1e-9 * (1.0 + loop.front().norm())) {
      fail(surface_id,
           "a loop winds around the periodic surface (no seam curve); tri needs "
           "loops that close in the parameter plane");
    }
    uv.push_back(std::move(loop));
  }
  // Holes: shift by whole periods so that each lies within the outer loop's range.
  for (int d = 0; d < 2; ++d) {
    if (period[d] <= 0.0) continue;
    double lo = uv[0][0][d];
    double hi = lo;
    for (const Vec2& p : uv[0]) {
      lo = std::min(lo, p[d]);
      hi = std::max(hi, p[d]);
    }
    for (size_t l = 1; l < uv.size(); ++l) {
      double mean = 0.0;
      for (const Vec2& p : uv[l]) mean += p[d];
      mean /= static_cast<double>(uv[l].size());
      const double shift =
          mean < lo ? period[d] * std::ceil((lo - mean) / period[d])
                    : (mean > hi ? -period[d] * std::ceil((mean - hi) / period[d]) : 0.0);
      for (Vec2& p : uv[l]) p[d] += shift;
    }
  }
  // Average |dS/du|, |dS/dv| over the boundary nodes (central differences).
  const auto bounds = g.uv_bounds();
  const double du = 1e-6 * std::max(1.0, bounds.second.x() - bounds.first.x());
  const double dv = 1e-6 * std::max(1.0, bounds.second.y() - bounds.first.y());
  double su = 0.0;
  double sv = 0.0;
  double orientation = 0.0;
  size_t count = 0;
  for (const auto& loop : uv) {
    for (const Vec2& p : loop) {
      const Vec3 Su = (g.point(p + Vec2(du, 0)) - g.point(p - Vec2(du, 0))) / (2 * du);
      const Vec3 Sv = (g.point(p + Vec2(0, dv)) - g.point(p - Vec2(0, dv))) / (2 * dv);
      su += Su.norm();
      sv += Sv.norm();
      orientation += Su.cross(Sv).dot(g.normal(p));
      ++count;
    }
  }
  su_ = su / static_cast<double>(count);
  sv_ = sv / static_cast<double>(count);
  if (!(su_ > 0.0) || !(sv_ > 0.0) || !std::isfinite(su_ + sv_)) {
    fail(surface_id, "degenerate surface parameterisation");
  }
  vsign_ = orientation < 0.0 ? -1.0 : 1.0;
  for (const auto& loop : uv) {
    std::vector<Vec2> flat;
    for (const Vec2& p : loop) flat.emplace_back(su_ * p.x(), vsign_ * sv_ * p.y());
    out.loops.push_back(std::move(flat));
  }
}

Vec2 FaceSpace::flat_planar(const Vec3& x) const {
  const Vec3 d = x - origin_;
  return {d.dot(ex_), d.dot(ey_)};
}

Vec3 FaceSpace::point(const Vec2& p) const {
  const geom::SurfaceGeometry& g = *surface_->geometry;
  if (planar_) return g.project(origin_ + p.x() * ex_ + p.y() * ey_).point;
  return g.project(g.point(Vec2(p.x() / su_, vsign_ * p.y() / sv_))).point;
}

Vec3 FaceSpace::normal(const Vec3& x) const {
  if (planar_) return n_;
  return surface_->geometry->project(x).normal;
}

}  // namespace cooperage::tri
