#include "analytic_model.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cooperage::testing {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// A unit vector orthogonal to z.
Vec3 any_orthogonal(const Vec3& z) {
  const Vec3 t = std::abs(z.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (t - t.dot(z) * z).normalized();
}

}  // namespace

double LineCurve::closest_parameter(const Vec3& p) const {
  const Vec3 d = b_ - a_;
  return std::clamp((p - a_).dot(d) / d.squaredNorm(), 0.0, 1.0);
}

CircleArc::CircleArc(Vec3 center, Vec3 axis, Vec3 x_dir, double radius, double t0, double t1)
    : c_(std::move(center)), z_(axis.normalized()), r_(radius), t0_(t0), t1_(t1) {
  x_ = (x_dir - x_dir.dot(z_) * z_).normalized();
  y_ = z_.cross(x_);
}

Vec3 CircleArc::point(double t) const { return c_ + r_ * (std::cos(t) * x_ + std::sin(t) * y_); }

Vec3 CircleArc::tangent(double t) const { return r_ * (-std::sin(t) * x_ + std::cos(t) * y_); }

double CircleArc::closest_parameter(const Vec3& p) const {
  const Vec3 d = p - c_;
  double t = std::atan2(d.dot(y_), d.dot(x_));
  while (t < t0_) t += kTwoPi;
  while (t >= t0_ + kTwoPi) t -= kTwoPi;
  if (t <= t1_) return t;
  return (t - t1_) < (t0_ + kTwoPi - t) ? t1_ : t0_;
}

PlaneSurface::PlaneSurface(Vec3 origin, Vec3 normal)
    : o_(std::move(origin)), n_(normal.normalized()) {
  x_ = any_orthogonal(n_);
  y_ = n_.cross(x_);
}

geom::SurfaceProjection PlaneSurface::project(const Vec3& p) const {
  const Vec3 d = p - o_;
  geom::SurfaceProjection out;
  out.point = p - d.dot(n_) * n_;
  out.normal = n_;
  out.uv = Vec2(d.dot(x_), d.dot(y_));
  out.distance = std::abs(d.dot(n_));
  return out;
}

CylinderSurface::CylinderSurface(Vec3 origin, Vec3 axis, double radius, bool outward)
    : o_(std::move(origin)), z_(axis.normalized()), r_(radius), sign_(outward ? 1.0 : -1.0) {
  x_ = any_orthogonal(z_);
  y_ = z_.cross(x_);
}

geom::SurfaceProjection CylinderSurface::project(const Vec3& p) const {
  const Vec3 d = p - o_;
  const double h = d.dot(z_);
  Vec3 radial = d - h * z_;
  if (radial.norm() < 1e-300) radial = x_;
  radial.normalize();
  geom::SurfaceProjection out;
  out.point = o_ + h * z_ + r_ * radial;
  out.normal = sign_ * radial;
  double a = std::atan2(radial.dot(y_), radial.dot(x_));
  if (a < 0) a += kTwoPi;
  out.uv = Vec2(a, h);
  out.distance = (p - out.point).norm();
  return out;
}

Vec3 CylinderSurface::point(const Vec2& uv) const {
  return o_ + uv.y() * z_ + r_ * (std::cos(uv.x()) * x_ + std::sin(uv.x()) * y_);
}

Vec3 CylinderSurface::normal(const Vec2& uv) const {
  return sign_ * (std::cos(uv.x()) * x_ + std::sin(uv.x()) * y_);
}

// ---- ModelBuilder -------------------------------------------------------------

int ModelBuilder::vertex(const Vec3& p) {
  geom::Vertex v;
  v.point = p;
  return model_.add_vertex(v);
}

int ModelBuilder::line(int a, int b) {
  geom::Curve c;
  c.start_vertex = a;
  c.end_vertex = b;
  c.geometry = std::make_shared<LineCurve>(model_.vertex(a).point, model_.vertex(b).point);
  const int id = model_.add_curve(std::move(c));
  between_[{std::min(a, b), std::max(a, b)}] = id;
  return id;
}

int ModelBuilder::arc(int a, int b, const Vec3& center, const Vec3& axis) {
  const Vec3 z = axis.normalized();
  const Vec3 da = model_.vertex(a).point - center;
  const Vec3 db = model_.vertex(b).point - center;
  const Vec3 x = (da - da.dot(z) * z).normalized();
  const Vec3 y = z.cross(x);
  double t1 = std::atan2(db.dot(y), db.dot(x));
  if (t1 <= 1e-12) t1 += kTwoPi;
  geom::Curve c;
  c.start_vertex = a;
  c.end_vertex = b;
  // Centre of the circle in the arc's plane (the start vertex's height along z).
  const Vec3 c0 = center + da.dot(z) * z;
  c.geometry = std::make_shared<CircleArc>(c0, z, x, (da - da.dot(z) * z).norm(), 0.0, t1);
  const int id = model_.add_curve(std::move(c));
  between_[{std::min(a, b), std::max(a, b)}] = id;
  return id;
}

int ModelBuilder::circle(int v, const Vec3& center, const Vec3& axis) {
  const Vec3 z = axis.normalized();
  const Vec3 d = model_.vertex(v).point - center;
  const Vec3 radial = d - d.dot(z) * z;
  geom::Curve c;
  c.start_vertex = v;
  c.end_vertex = v;
  c.geometry =
      std::make_shared<CircleArc>(center + d.dot(z) * z, z, radial, radial.norm(), 0.0, kTwoPi);
  return model_.add_curve(std::move(c));
}

geom::Loop ModelBuilder::loop(const std::vector<int>& vertices) {
  geom::Loop out;
  for (size_t k = 0; k < vertices.size(); ++k) {
    const int a = vertices[k], b = vertices[(k + 1) % vertices.size()];
    auto it = between_.find({std::min(a, b), std::max(a, b)});
    const int curve = it != between_.end() ? it->second : line(a, b);
    const geom::Curve& c = model_.curve(curve);
    out.uses.push_back({curve, c.start_vertex == a ? geom::Sense::Forward : geom::Sense::Reversed});
  }
  return out;
}

int ModelBuilder::surface(std::shared_ptr<const geom::SurfaceGeometry> geometry,
                          std::vector<geom::Loop> loops) {
  geom::Surface s;
  s.geometry = std::move(geometry);
  s.loops = std::move(loops);
  return model_.add_surface(std::move(s));
}

int ModelBuilder::planar(const std::vector<int>& outer,
                         const std::vector<std::vector<int>>& holes) {
  Vec3 n = Vec3::Zero();
  for (size_t k = 0; k < outer.size(); ++k) {
    const Vec3& p = model_.vertex(outer[k]).point;
    const Vec3& q = model_.vertex(outer[(k + 1) % outer.size()]).point;
    n += p.cross(q);
  }
  std::vector<geom::Loop> loops{loop(outer)};
  for (const auto& h : holes) loops.push_back(loop(h));
  return surface(std::make_shared<PlaneSurface>(model_.vertex(outer.front()).point, n),
                 std::move(loops));
}

int ModelBuilder::volume(const std::vector<int>& surfaces) {
  geom::Volume v;
  std::vector<geom::SurfaceUse> shell;
  const int id = static_cast<int>(model_.volumes().size()) + 1;
  for (int s : surfaces) {
    auto& owners = model_.mutable_surface(s).volumes;
    shell.push_back({s, owners.empty() ? geom::Sense::Forward : geom::Sense::Reversed});
    owners.push_back(id);
  }
  v.shells.push_back(std::move(shell));
  return model_.add_volume(std::move(v));
}

geom::Model ModelBuilder::finish() {
  for (const auto& c : model_.curves()) {
    geom::Curve& mc = model_.mutable_curve(c.id);
    mc.length = c.geometry->length();
    for (int v : {c.start_vertex, c.end_vertex}) {
      auto& list = model_.mutable_vertex(v).curves;
      if (std::find(list.begin(), list.end(), c.id) == list.end()) list.push_back(c.id);
    }
  }
  for (const auto& s : model_.surfaces()) {
    geom::Surface& ms = model_.mutable_surface(s.id);
    for (const auto& l : s.loops) {
      for (const auto& use : l.uses) {
        auto& list = model_.mutable_curve(use.curve).surfaces;
        if (std::find(list.begin(), list.end(), s.id) == list.end()) list.push_back(s.id);
        const auto& g = *model_.curve(use.curve).geometry;
        const auto [t0, t1] = g.range();
        for (int k = 0; k <= 8; ++k) ms.box.add(g.point(t0 + (t1 - t0) * k / 8.0));
      }
    }
  }
  for (const auto& v : model_.vertices()) {
    std::sort(model_.mutable_vertex(v.id).curves.begin(), model_.mutable_vertex(v.id).curves.end());
  }
  for (const auto& c : model_.curves()) {
    std::sort(model_.mutable_curve(c.id).surfaces.begin(),
              model_.mutable_curve(c.id).surfaces.end());
  }
  for (const auto& v : model_.volumes()) {
    for (int s : model_.surfaces_of(v.id))
      model_.mutable_volume(v.id).box.add(model_.surface(s).box);
  }
  model_.validate();
  return std::move(model_);
}

// ---- models ---------------------------------------------------------------------

geom::Model rectangle_model(double a, double b) {
  ModelBuilder m;
  const int v1 = m.vertex({0, 0, 0}), v2 = m.vertex({a, 0, 0});
  const int v3 = m.vertex({a, b, 0}), v4 = m.vertex({0, b, 0});
  m.planar({v1, v2, v3, v4});
  return m.finish();
}

geom::Model l_shape_model() {
  ModelBuilder m;
  std::vector<int> v;
  for (const auto& p :
       {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 2, 0), Vec3(0, 2, 0)}) {
    v.push_back(m.vertex(p));
  }
  m.planar(v);
  return m.finish();
}

geom::Model square_with_hole_model() {
  ModelBuilder m;
  const int v1 = m.vertex({0, 0, 0}), v2 = m.vertex({3, 0, 0});
  const int v3 = m.vertex({3, 3, 0}), v4 = m.vertex({0, 3, 0});
  const int h1 = m.vertex({1, 1, 0}), h2 = m.vertex({1, 2, 0});
  const int h3 = m.vertex({2, 2, 0}), h4 = m.vertex({2, 1, 0});
  m.planar({v1, v2, v3, v4}, {{h1, h2, h3, h4}});
  return m.finish();
}

geom::Model brick_model(double a, double b, double c) {
  ModelBuilder m;
  const int v1 = m.vertex({0, 0, 0}), v2 = m.vertex({a, 0, 0});
  const int v3 = m.vertex({a, b, 0}), v4 = m.vertex({0, b, 0});
  const int v5 = m.vertex({0, 0, c}), v6 = m.vertex({a, 0, c});
  const int v7 = m.vertex({a, b, c}), v8 = m.vertex({0, b, c});
  std::vector<int> faces;
  faces.push_back(m.planar({v1, v4, v3, v2}));  // z = 0
  faces.push_back(m.planar({v5, v6, v7, v8}));  // z = c
  faces.push_back(m.planar({v1, v2, v6, v5}));  // y = 0
  faces.push_back(m.planar({v4, v8, v7, v3}));  // y = b
  faces.push_back(m.planar({v1, v5, v8, v4}));  // x = 0
  faces.push_back(m.planar({v2, v3, v7, v6}));  // x = a
  m.volume(faces);
  return m.finish();
}

geom::Model split_top_brick_model() {
  ModelBuilder m;
  const int v1 = m.vertex({0, 0, 0}), v2 = m.vertex({2, 0, 0});
  const int v3 = m.vertex({2, 2, 0}), v4 = m.vertex({0, 2, 0});
  const int v5 = m.vertex({0, 0, 1}), v6 = m.vertex({2, 0, 1});
  const int v7 = m.vertex({2, 2, 1}), v8 = m.vertex({0, 2, 1});
  const int v9 = m.vertex({1, 0, 1}), v10 = m.vertex({1, 2, 1});
  std::vector<int> faces;
  faces.push_back(m.planar({v1, v4, v3, v2}));
  faces.push_back(m.planar({v5, v9, v10, v8}));
  faces.push_back(m.planar({v9, v6, v7, v10}));
  faces.push_back(m.planar({v1, v2, v6, v9, v5}));
  faces.push_back(m.planar({v4, v8, v10, v7, v3}));
  faces.push_back(m.planar({v1, v5, v8, v4}));
  faces.push_back(m.planar({v2, v3, v7, v6}));
  m.volume(faces);
  return m.finish();
}

geom::Model quarter_annulus_model() {
  ModelBuilder m;
  const int v1 = m.vertex({1, 0, 0}), v2 = m.vertex({2, 0, 0});
  const int v3 = m.vertex({0, 2, 0}), v4 = m.vertex({0, 1, 0});
  m.arc(v2, v3, Vec3::Zero(), Vec3::UnitZ());
  m.arc(v1, v4, Vec3::Zero(), Vec3::UnitZ());
  m.planar({v1, v2, v3, v4});
  return m.finish();
}

geom::Model quarter_annulus_block_model() {
  ModelBuilder m;
  const int v1 = m.vertex({1, 0, 0}), v2 = m.vertex({2, 0, 0});
  const int v3 = m.vertex({0, 2, 0}), v4 = m.vertex({0, 1, 0});
  const int v5 = m.vertex({1, 0, 1}), v6 = m.vertex({2, 0, 1});
  const int v7 = m.vertex({0, 2, 1}), v8 = m.vertex({0, 1, 1});
  const Vec3 z = Vec3::UnitZ();
  m.arc(v2, v3, Vec3::Zero(), z);
  m.arc(v1, v4, Vec3::Zero(), z);
  m.arc(v6, v7, Vec3::Zero(), z);
  m.arc(v5, v8, Vec3::Zero(), z);
  std::vector<int> faces;
  faces.push_back(m.planar({v1, v4, v3, v2}));  // z = 0
  faces.push_back(m.planar({v5, v6, v7, v8}));  // z = 1
  faces.push_back(m.planar({v1, v2, v6, v5}));  // y = 0
  faces.push_back(m.planar({v4, v8, v7, v3}));  // x = 0
  faces.push_back(m.surface(std::make_shared<CylinderSurface>(Vec3::Zero(), z, 2.0, true),
                            {m.loop({v2, v3, v7, v6})}));
  faces.push_back(m.surface(std::make_shared<CylinderSurface>(Vec3::Zero(), z, 1.0, false),
                            {m.loop({v1, v5, v8, v4})}));
  m.volume(faces);
  return m.finish();
}

geom::Model cylinder_side_model(double r, double h) {
  ModelBuilder m;
  const int v1 = m.vertex({r, 0, 0}), v2 = m.vertex({r, 0, h});
  const Vec3 z = Vec3::UnitZ();
  const int bottom = m.circle(v1, Vec3::Zero(), z);
  const int top = m.circle(v2, Vec3(0, 0, h), z);
  const int seam = m.line(v1, v2);
  geom::Loop loop;
  loop.uses = {{bottom, geom::Sense::Forward},
               {seam, geom::Sense::Forward},
               {top, geom::Sense::Reversed},
               {seam, geom::Sense::Reversed}};
  m.surface(std::make_shared<CylinderSurface>(Vec3::Zero(), z, r, true), {loop});
  return m.finish();
}

}  // namespace cooperage::testing
