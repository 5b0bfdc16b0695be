// Workbench primitives: brick, cylinder, cone, sphere, prism, revolve and a
// B-spline patch. Arguments are validated before OCCT sees them.
#include "framework/geometry/occ/detail.h"

#include <Eigen/Geometry>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pln.hxx>

#include <cmath>

namespace cooperage::occ {
namespace detail {

Vec3 newell(const std::vector<Vec3>& pts) {
  Vec3 n = Vec3::Zero();
  for (size_t i = 0; i < pts.size(); ++i) n += pts[i].cross(pts[(i + 1) % pts.size()]);
  return n;
}

double extent(const std::vector<Vec3>& pts) {
  geom::BoundingBox b;
  for (const auto& p : pts) b.add(p);
  return b.diagonal();
}

Vec3 check_polygon(const std::string& shape, const std::vector<Vec3>& pts, const char* what) {
  if (pts.size() < 3) invalid(shape, std::string(what) + " needs at least 3 points");
  for (const auto& p : pts)
    if (!p.allFinite()) invalid(shape, std::string(what) + " has a non-finite point");
  const double size = extent(pts);
  const Vec3 n = newell(pts);
  if (!(size > 0.0) || n.norm() <= 1e-12 * size * size)
    invalid(shape, std::string(what) + " is degenerate (zero area)");
  for (size_t i = 0; i < pts.size(); ++i)
    if ((pts[i] - pts[(i + 1) % pts.size()]).norm() <= 1e-9 * size)
      invalid(shape, std::string(what) + " has coincident consecutive points");
  return n.normalized();
}

void check_in_plane(const std::string& shape, const std::vector<Vec3>& pts, const Vec3& origin,
                    const Vec3& n, double size, const char* what) {
  for (const auto& p : pts)
    if (std::abs((p - origin).dot(n)) > 1e-7 * size)
      invalid(shape, std::string(what) + " is not planar");
}

TopoDS_Wire polygon_wire(const std::vector<Vec3>& pts) {
  BRepBuilderAPI_MakePolygon poly;
  for (const auto& p : pts) poly.Add(detail::to_pnt(p));
  poly.Close();
  if (!poly.IsDone()) throw MeshingError(ErrorCode::GeometryError, "polygon construction failed");
  return poly.Wire();
}

void check_valid(const std::string& shape, const TopoDS_Shape& s) {
  if (s.IsNull() || !BRepCheck_Analyzer(s).IsValid())
    throw MeshingError(ErrorCode::GeometryError,
                       "shape '" + shape + "': the kernel built an invalid solid");
}

}  // namespace detail

namespace {

using detail::check_in_plane;
using detail::check_polygon;
using detail::check_valid;
using detail::extent;
using detail::invalid;
using detail::polygon_wire;

void positive(const std::string& shape, double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    invalid(shape, std::string(what) + " must be positive, got " + detail::num(value));
}

/// Planar face bounded by `profile` (made counter-clockwise about the plane
/// normal) with `holes` (made clockwise).
TopoDS_Face planar_face(const std::string& shape, const std::vector<Vec3>& profile,
                        const std::vector<std::vector<Vec3>>& holes) {
  const Vec3 n = check_polygon(shape, profile, "profile");
  const double size = extent(profile);
  check_in_plane(shape, profile, profile.front(), n, size, "profile");
  const gp_Pln plane(detail::to_pnt(profile.front()), gp_Dir(n.x(), n.y(), n.z()));
  BRepBuilderAPI_MakeFace mf(plane, polygon_wire(profile), Standard_True);
  if (!mf.IsDone()) invalid(shape, "cannot make a face from the profile");
  for (const auto& hole : holes) {
    const Vec3 hn = check_polygon(shape, hole, "hole");
    check_in_plane(shape, hole, profile.front(), n, size, "hole");
    std::vector<Vec3> pts = hole;
    if (hn.dot(n) > 0) pts.assign(hole.rbegin(), hole.rend());
    mf.Add(polygon_wire(pts));
  }
  const TopoDS_Face face = mf.Face();
  if (!BRepCheck_Analyzer(face).IsValid())
    invalid(shape, "profile and holes do not make a valid face (holes outside or crossing?)");
  return face;
}

}  // namespace

void Workbench::brick(const std::string& name, const Vec3& origin, const Vec3& size) {
  impl_->check_new_name(name);
  for (int i = 0; i < 3; ++i) positive(name, size[i], "brick size");
  if (!origin.allFinite()) invalid(name, "origin must be finite");
  impl_->add(
      name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
        return BRepPrimAPI_MakeBox(detail::to_pnt(origin), size.x(), size.y(), size.z()).Shape();
      }));
}

void Workbench::cylinder(const std::string& name, const Vec3& base, const Vec3& axis, double radius,
                         double height) {
  impl_->check_new_name(name);
  positive(name, radius, "radius");
  positive(name, height, "height");
  const gp_Dir dir = detail::checked_dir(name, axis, "axis");
  impl_->add(
      name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
        return BRepPrimAPI_MakeCylinder(gp_Ax2(detail::to_pnt(base), dir), radius, height).Shape();
      }));
}

void Workbench::cone(const std::string& name, const Vec3& base, const Vec3& axis, double radius1,
                     double radius2, double height) {
  impl_->check_new_name(name);
  if (!(radius1 >= 0.0) || !(radius2 >= 0.0) || !std::isfinite(radius1) || !std::isfinite(radius2))
    invalid(name, "cone radii must be non-negative");
  if (radius1 <= 0.0 && radius2 <= 0.0) invalid(name, "cone radii cannot both be zero");
  positive(name, height, "height");
  const gp_Dir dir = detail::checked_dir(name, axis, "axis");
  impl_->add(name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
               const gp_Ax2 ax(detail::to_pnt(base), dir);
               if (std::abs(radius1 - radius2) <= 1e-12 * std::max(radius1, radius2))
                 return BRepPrimAPI_MakeCylinder(ax, radius1, height).Shape();
               return BRepPrimAPI_MakeCone(ax, radius1, radius2, height).Shape();
             }));
}

void Workbench::sphere(const std::string& name, const Vec3& center, double radius) {
  impl_->check_new_name(name);
  positive(name, radius, "radius");
  impl_->add(name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
               return BRepPrimAPI_MakeSphere(detail::to_pnt(center), radius).Shape();
             }));
}

void Workbench::torus(const std::string& name, const Vec3& center, const Vec3& axis,
                      double major_radius, double minor_radius) {
  impl_->check_new_name(name);
  positive(name, major_radius, "major radius");
  positive(name, minor_radius, "minor radius");
  if (!axis.allFinite() || axis.norm() <= 0.0) invalid(name, "axis must be a non-zero vector");
  if (minor_radius >= major_radius)
    invalid(name, "minor radius must be less than the major radius");
  impl_->add(name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
               const gp_Ax2 frame(detail::to_pnt(center), gp_Dir(axis.x(), axis.y(), axis.z()));
               return BRepPrimAPI_MakeTorus(frame, major_radius, minor_radius).Shape();
             }));
}

void Workbench::prism(const std::string& name, const std::vector<Vec3>& profile,
                      const std::vector<std::vector<Vec3>>& holes, const Vec3& direction) {
  impl_->check_new_name(name);
  if (!direction.allFinite() || direction.norm() <= 0.0)
    invalid(name, "extrusion direction must be a non-zero vector");
  impl_->add(name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
               const TopoDS_Face face = planar_face(name, profile, holes);
               const Vec3 n = check_polygon(name, profile, "profile");
               if (std::abs(direction.normalized().dot(n)) < 1e-9)
                 invalid(name, "extrusion direction lies in the profile plane");
               BRepPrimAPI_MakePrism mk(face, detail::to_vec(direction));
               const TopoDS_Shape s = mk.Shape();
               check_valid(name, s);
               return s;
             }));
}

void Workbench::revolve(const std::string& name, const std::vector<Vec3>& profile,
                        const Vec3& origin, const Vec3& axis, double angle_deg) {
  impl_->check_new_name(name);
  const gp_Dir dir = detail::checked_dir(name, axis, "axis");
  if (!(angle_deg > 0.0) || !(angle_deg <= 360.0))
    invalid(name, "revolution angle must be in (0, 360] degrees, got " + detail::num(angle_deg));
  impl_->add(name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
               const TopoDS_Face face = planar_face(name, profile, {});
               const gp_Ax1 ax(detail::to_pnt(origin), dir);
               TopoDS_Shape s =
                   angle_deg >= 360.0
                       ? BRepPrimAPI_MakeRevol(face, ax).Shape()
                       : BRepPrimAPI_MakeRevol(face, ax, angle_deg * M_PI / 180.0).Shape();
               check_valid(name, s);
               return s;
             }));
}

void Workbench::bspline_patch(const std::string& name, const std::vector<std::vector<Vec3>>& grid,
                              double thickness) {
  impl_->check_new_name(name);
  if (grid.size() < 2 || grid.front().size() < 2)
    invalid(name, "a B-spline patch needs at least a 2 x 2 grid");
  for (const auto& row : grid) {
    if (row.size() != grid.front().size()) invalid(name, "grid rows differ in length");
    for (const auto& p : row)
      if (!p.allFinite()) invalid(name, "grid has a non-finite point");
  }
  if (!std::isfinite(thickness)) invalid(name, "thickness must be finite");
  impl_->add(name, detail::guarded(ErrorCode::GeometryError, "shape '" + name + "'", [&] {
               const int nu = static_cast<int>(grid.size());
               const int nv = static_cast<int>(grid.front().size());
               TColgp_Array2OfPnt pts(1, nu, 1, nv);
               for (int i = 0; i < nu; ++i)
                 for (int j = 0; j < nv; ++j)
                   pts.SetValue(i + 1, j + 1, detail::to_pnt(grid[i][j]));
               GeomAPI_PointsToBSplineSurface fit(pts, 3, 8, GeomAbs_C2, 1e-9);
               if (!fit.IsDone()) invalid(name, "cannot fit a B-spline surface through the grid");
               Handle(Geom_BSplineSurface) surf = fit.Surface();
               BRepBuilderAPI_MakeFace mf(surf, 1e-9);
               if (!mf.IsDone()) invalid(name, "cannot make a face on the B-spline surface");
               const TopoDS_Face face = mf.Face();
               if (thickness == 0.0) return TopoDS_Shape(face);
               // Mean normal of the grid (sum of cell cross products).
               Vec3 n = Vec3::Zero();
               for (int i = 0; i + 1 < nu; ++i)
                 for (int j = 0; j + 1 < nv; ++j)
                   n += (grid[i + 1][j] - grid[i][j]).cross(grid[i][j + 1] - grid[i][j]);
               if (n.norm() <= 0.0) invalid(name, "degenerate grid (no mean normal)");
               const TopoDS_Shape s =
                   BRepPrimAPI_MakePrism(face, detail::to_vec(n.normalized() * thickness)).Shape();
               check_valid(name, s);
               return s;
             }));
}

}  // namespace cooperage::occ
