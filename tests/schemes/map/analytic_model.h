// Test-only analytic geometry (lines, circular arcs, planes, cylinders) and
// builders of small B-rep models, so scheme tests run without a CAD kernel.
// Loops are given with the face on the left seen against the natural normal.
#pragma once

#include "framework/geometry/model.h"

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace cooperage::testing {

using geom::Vec2;
using geom::Vec3;

/// Straight segment a -> b, t in [0, 1].
class LineCurve final : public geom::CurveGeometry {
 public:
  LineCurve(Vec3 a, Vec3 b) : a_(std::move(a)), b_(std::move(b)) {}
  geom::CurveType type() const override { return geom::CurveType::Line; }
  std::pair<double, double> range() const override { return {0.0, 1.0}; }
  Vec3 point(double t) const override { return a_ + t * (b_ - a_); }
  Vec3 tangent(double) const override { return b_ - a_; }
  double length(double a, double b) const override { return (b - a) * (b_ - a_).norm(); }
  double closest_parameter(const Vec3& p) const override;
  double parameter_at_length(double s) const override { return s / (b_ - a_).norm(); }

 private:
  Vec3 a_, b_;
};

/// Circle arc about `axis` through center: point(t) = c + r (cos t x + sin t y),
/// y = axis x x, t in [t0, t1] (counter-clockwise about axis).
class CircleArc final : public geom::CurveGeometry {
 public:
  CircleArc(Vec3 center, Vec3 axis, Vec3 x_dir, double radius, double t0, double t1);
  geom::CurveType type() const override { return geom::CurveType::Circle; }
  std::pair<double, double> range() const override { return {t0_, t1_}; }
  Vec3 point(double t) const override;
  Vec3 tangent(double t) const override;
  double length(double a, double b) const override { return r_ * (b - a); }
  double closest_parameter(const Vec3& p) const override;
  double parameter_at_length(double s) const override { return t0_ + s / r_; }

 private:
  Vec3 c_, z_, x_, y_;
  double r_, t0_, t1_;
};

/// Plane through origin with unit normal n (the natural normal).
class PlaneSurface final : public geom::SurfaceGeometry {
 public:
  PlaneSurface(Vec3 origin, Vec3 normal);
  geom::SurfaceType type() const override { return geom::SurfaceType::Plane; }
  geom::SurfaceProjection project(const Vec3& p) const override;
  Vec3 point(const Vec2& uv) const override { return o_ + uv.x() * x_ + uv.y() * y_; }
  Vec3 normal(const Vec2&) const override { return n_; }
  std::pair<Vec2, Vec2> uv_bounds() const override { return {Vec2(-1e6, 1e6), Vec2(-1e6, 1e6)}; }

 private:
  Vec3 o_, n_, x_, y_;
};

/// Cylinder about the axis through origin; natural normal radially outward
/// when outward is true, toward the axis otherwise. uv = (angle, height).
class CylinderSurface final : public geom::SurfaceGeometry {
 public:
  CylinderSurface(Vec3 origin, Vec3 axis, double radius, bool outward);
  geom::SurfaceType type() const override { return geom::SurfaceType::Cylinder; }
  geom::SurfaceProjection project(const Vec3& p) const override;
  Vec3 point(const Vec2& uv) const override;
  Vec3 normal(const Vec2& uv) const override;
  std::pair<Vec2, Vec2> uv_bounds() const override {
    return {Vec2(0.0, 6.283185307179586), Vec2(-1e6, 1e6)};
  }

 private:
  Vec3 o_, z_, x_, y_;
  double r_;
  double sign_;
};

/// Assembles a geom::Model: vertices, curves, surfaces from loops, volumes;
/// finish() fills the back references, lengths and boxes, and validates.
class ModelBuilder {
 public:
  int vertex(const Vec3& p);
  /// A straight curve a -> b.
  int line(int a, int b);
  /// A circle arc a -> b counter-clockwise about axis through center.
  int arc(int a, int b, const Vec3& center, const Vec3& axis);
  /// A closed circle starting and ending at vertex v, counter-clockwise about axis.
  int circle(int v, const Vec3& center, const Vec3& axis);
  /// The loop through the vertices (closed implicitly), using an existing
  /// curve between consecutive vertices or a new line.
  geom::Loop loop(const std::vector<int>& vertices);
  /// A surface with the given loops (outer first).
  int surface(std::shared_ptr<const geom::SurfaceGeometry> geometry, std::vector<geom::Loop> loops);
  /// A planar surface whose outer loop runs through the vertices
  /// counter-clockwise about its natural normal (computed by Newell's method).
  int planar(const std::vector<int>& outer, const std::vector<std::vector<int>>& holes = {});
  /// A volume bounded by the surfaces; the first volume of a surface gets Forward.
  int volume(const std::vector<int>& surfaces);
  geom::Model finish();

  geom::Model& model() { return model_; }

 private:
  geom::Model model_;
  std::map<std::pair<int, int>, int> between_;  // (min, max vertex) -> curve
};

/// Rectangle [0,a] x [0,b] in z = 0, natural normal +z (free surface 1).
geom::Model rectangle_model(double a, double b);
/// L-shaped face (0,0),(2,0),(2,1),(1,1),(1,2),(0,2): vertex 4 is a CORNER.
geom::Model l_shape_model();
/// Square [0,3]^2 with a square hole [1,2]^2.
geom::Model square_with_hole_model();
/// Brick [0,a] x [0,b] x [0,c] as volume 1 with 6 planar faces.
geom::Model brick_model(double a, double b, double c);
/// Brick [0,2]x[0,2]x[0,1] whose top is split into two faces at x = 1 (7 faces).
geom::Model split_top_brick_model();
/// Quarter annulus r in [1, 2], angle in [0, 90] degrees, z = 0, normal +z.
geom::Model quarter_annulus_model();
/// The quarter annulus extruded to height 1: 4 planes + 2 cylinder faces.
geom::Model quarter_annulus_block_model();
/// Side face of a cylinder (radius r, height h, axis z) with a seam curve:
/// loop = bottom circle, seam, top circle reversed, seam reversed.
geom::Model cylinder_side_model(double r, double h);

}  // namespace cooperage::testing
