// The tight bounding box of a face, without a particle swarm where the
// surface's own form says where its extremes are.
//
// A coordinate's extreme over a face lies on the face's boundary or at an
// interior point where the surface's normal is parallel to that axis. On a
// plane there is none; on a cylinder or a cone such points form whole
// generatrices (the coordinate is linear along them), which run into the
// boundary, so the edges carry the extreme; a sphere has two per axis and a
// torus four; on a B-spline they are found from a grid of samples and
// Newton's method. The box is therefore the union of the edges' tight
// boxes, the vertices (a cone's apex, a sphere's pole) and those points that
// lie on the face. BRepBndLib::AddOptimal instead bounds the face's whole
// parameter rectangle (a swarm search on a torus or a B-spline) and then
// shrinks each side back to the edges' box where a surface-plane extremum
// lies outside the face: a quarter to 40 % of the decomposition's refusal
// of occt_bottle went there, on the torus and plane pieces every candidate
// cut makes (issue 16). On cut B-spline faces its boxes also missed up to 2
// % of the face and reached 10 % past it (bench/RESULTS.md, session 49).
#include "framework/geometry/occ/detail.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <BndLib_Add3dCurve.hxx>
#include <Bnd_Box.hxx>
#include <ElSLib.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt2d.hxx>

#include <cmath>
#include <optional>
#include <vector>

namespace cooperage::occ::detail {
namespace {

const gp_Dir kAxes[3] = {gp_Dir(1, 0, 0), gp_Dir(0, 1, 0), gp_Dir(0, 0, 1)};

// A point of the surface that may bound the face, with its parameters.
struct Candidate {
  gp_Pnt point;
  gp_Pnt2d uv;
};

// A sphere's points where the normal is parallel to an axis: centre +- r e.
void sphere_points(const gp_Sphere& s, std::vector<Candidate>& out) {
  for (const gp_Dir& e : kAxes)
    for (const double side : {-1.0, 1.0}) {
      const gp_Pnt p = s.Location().Translated(gp_Vec(e) * (side * s.Radius()));
      double u = 0.0, v = 0.0;
      ElSLib::Parameters(s, p, u, v);
      out.push_back({p, gp_Pnt2d(u, v)});
    }
}

// A torus's: at the angle u where the axis direction e lies in the
// meridian plane, the tube's circles on both sides of the axis, each at +- r
// along e.
void torus_points(const gp_Torus& t, std::vector<Candidate>& out) {
  const gp_Ax3& frame = t.Position();
  for (const gp_Dir& e : kAxes) {
    const double a = gp_Vec(e).Dot(gp_Vec(frame.XDirection()));
    const double b = gp_Vec(e).Dot(gp_Vec(frame.YDirection()));
    const double u = std::atan2(b, a);
    const gp_Vec radial =
        gp_Vec(frame.XDirection()) * std::cos(u) + gp_Vec(frame.YDirection()) * std::sin(u);
    for (const double across : {-1.0, 1.0}) {
      const gp_Pnt centre = frame.Location().Translated(radial * (across * t.MajorRadius()));
      for (const double side : {-1.0, 1.0}) {
        const gp_Pnt p = centre.Translated(gp_Vec(e) * (side * t.MinorRadius()));
        double pu = 0.0, pv = 0.0;
        ElSLib::Parameters(t, p, pu, pv);
        out.push_back({p, gp_Pnt2d(pu, pv)});
      }
    }
  }
}

// A B-spline's: each coordinate's interior maxima and minima, found as
// the local extremes of a grid of samples over the face's parameter box and
// refined by Newton's method on the gradient (the sample itself when Newton
// does not converge inside the box or ends lower). Extremes on the box's
// rim are the face's edges' or off the face.
void spline_points(const BRepAdaptor_Surface& s, double u0, double u1, double v0, double v1,
                   std::vector<Candidate>& out) {
  constexpr int kGrid = 12;
  const double du = (u1 - u0) / kGrid, dv = (v1 - v0) / kGrid;
  if (!(du > 0.0) || !(dv > 0.0)) return;
  std::vector<gp_Pnt> grid(static_cast<size_t>((kGrid + 1) * (kGrid + 1)));
  const auto at = [&](int i, int j) -> gp_Pnt& {
    return grid[static_cast<size_t>(i * (kGrid + 1) + j)];
  };
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= kGrid; ++j) at(i, j) = s.Value(u0 + i * du, v0 + j * dv);
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {-1.0, 1.0}) {
      const auto f = [&](const gp_Pnt& p) { return sign * p.Coord(axis + 1); };
      for (int i = 1; i < kGrid; ++i) {
        for (int j = 1; j < kGrid; ++j) {
          const double here = f(at(i, j));
          bool peak = true;
          for (int a = -1; a <= 1 && peak; ++a)
            for (int b = -1; b <= 1 && peak; ++b)
              if ((a != 0 || b != 0) && f(at(i + a, j + b)) > here) peak = false;
          if (!peak) continue;
          double u = u0 + i * du, v = v0 + j * dv;
          bool converged = false;
          for (int it = 0; it < 30 && !converged; ++it) {
            gp_Pnt p;
            gp_Vec su, sv, suu, svv, suv;
            s.D2(u, v, p, su, sv, suu, svv, suv);
            const double gu = sign * su.Coord(axis + 1), gv = sign * sv.Coord(axis + 1);
            const double huu = sign * suu.Coord(axis + 1), hvv = sign * svv.Coord(axis + 1);
            const double huv = sign * suv.Coord(axis + 1);
            const double det = huu * hvv - huv * huv;
            if (!(std::abs(det) > 0.0)) break;
            const double step_u = -(hvv * gu - huv * gv) / det;
            const double step_v = -(huu * gv - huv * gu) / det;
            u += step_u;
            v += step_v;
            if (u < u0 || u > u1 || v < v0 || v > v1) break;
            converged =
                std::abs(step_u) <= 1e-12 * (u1 - u0) && std::abs(step_v) <= 1e-12 * (v1 - v0);
          }
          if (converged) {
            const gp_Pnt refined = s.Value(u, v);
            if (f(refined) >= here) {
              out.push_back({refined, gp_Pnt2d(u, v)});
              continue;
            }
          }
          out.push_back({at(i, j), gp_Pnt2d(u0 + i * du, v0 + j * dv)});
        }
      }
    }
  }
}

geom::BoundingBox to_box(const Bnd_Box& b) {
  geom::BoundingBox out;
  if (b.IsVoid()) return out;
  double x0, y0, z0, x1, y1, z1;
  b.Get(x0, y0, z0, x1, y1, z1);
  out.add(geom::Vec3(x0, y0, z0));
  out.add(geom::Vec3(x1, y1, z1));
  return out;
}

geom::BoundingBox swarm_box(const TopoDS_Face& face) {
  Bnd_Box b;
  BRepBndLib::AddOptimal(face, b, Standard_False, Standard_False);
  return to_box(b);
}

}  // namespace

geom::BoundingBox tight_face_box(const TopoDS_Face& face) {
  const BRepAdaptor_Surface surface(face, Standard_False);
  std::vector<Candidate> inner;
  switch (surface.GetType()) {
    case GeomAbs_Plane:
    case GeomAbs_Cylinder:
    case GeomAbs_Cone: break;
    case GeomAbs_Sphere: sphere_points(surface.Sphere(), inner); break;
    case GeomAbs_Torus: torus_points(surface.Torus(), inner); break;
    case GeomAbs_BSplineSurface:
    case GeomAbs_BezierSurface: {
      double u0, u1, v0, v1;
      BRepTools::UVBounds(face, u0, u1, v0, v1);
      spline_points(surface, u0, u1, v0, v1, inner);
      break;
    }
    default: return swarm_box(face);
  }
  Bnd_Box box;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::Degenerated(edge)) continue;
    if (!BRep_Tool::IsGeometric(edge)) return swarm_box(face);
    Bnd_Box b;
    BndLib_Add3dCurve::AddOptimal(BRepAdaptor_Curve(edge), 0.0, b);
    box.Add(b);
  }
  for (TopExp_Explorer it(face, TopAbs_VERTEX); it.More(); it.Next())
    box.Add(BRep_Tool::Pnt(TopoDS::Vertex(it.Current())));
  std::optional<BRepTopAdaptor_FClass2d> classify;
  for (const Candidate& c : inner) {
    if (!box.IsOut(c.point)) continue;
    if (!classify) classify.emplace(face, Precision::PConfusion());
    if (classify->Perform(c.uv) != TopAbs_OUT) box.Add(c.point);
  }
  return to_box(box);
}

}  // namespace cooperage::occ::detail
