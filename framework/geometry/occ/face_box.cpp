// The tight bounding box of a face, without a particle swarm where the
// surface's own form says where its extremes are.
//
// A coordinate's extreme over a face lies on the face's boundary or at an
// interior point where the surface's normal is parallel to that axis. On a
// plane there is none; on a cylinder or a cone such points form whole
// generatrices (the coordinate is linear along them), which run into the
// boundary, so the edges carry the extreme; a sphere has two per axis and a
// torus four. The box is therefore the union of the edges' tight boxes, the
// vertices (a cone's apex, a sphere's pole) and those points that lie on the
// face. BRepBndLib::AddOptimal instead bounds the face's whole parameter
// rectangle (a swarm search on a torus) and then shrinks each side back to
// the edges' box where a surface-plane extremum lies outside the face: 40 %
// of the decomposition's refusal of occt_bottle went there, on the torus
// and plane pieces every candidate cut makes (issue 16).
#include "framework/geometry/occ/detail.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
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
#include <vector>

namespace cooperage::occ::detail {
namespace {

const gp_Dir kAxes[3] = {gp_Dir(1, 0, 0), gp_Dir(0, 1, 0), gp_Dir(0, 0, 1)};

// A sphere's points where the normal is parallel to an axis: centre +- r e.
void sphere_points(const gp_Sphere& s, std::vector<gp_Pnt>& out) {
  for (const gp_Dir& e : kAxes)
    for (const double side : {-1.0, 1.0})
      out.push_back(s.Location().Translated(gp_Vec(e) * (side * s.Radius())));
}

// A torus's: at the angle u where the axis direction e lies in the
// meridian plane, the tube's circles on both sides of the axis, each at +- r
// along e.
void torus_points(const gp_Torus& t, std::vector<gp_Pnt>& out) {
  const gp_Ax3& frame = t.Position();
  for (const gp_Dir& e : kAxes) {
    const double a = gp_Vec(e).Dot(gp_Vec(frame.XDirection()));
    const double b = gp_Vec(e).Dot(gp_Vec(frame.YDirection()));
    const double u = std::atan2(b, a);
    const gp_Vec radial =
        gp_Vec(frame.XDirection()) * std::cos(u) + gp_Vec(frame.YDirection()) * std::sin(u);
    for (const double across : {-1.0, 1.0}) {
      const gp_Pnt centre = frame.Location().Translated(radial * (across * t.MajorRadius()));
      for (const double side : {-1.0, 1.0})
        out.push_back(centre.Translated(gp_Vec(e) * (side * t.MinorRadius())));
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
  std::vector<gp_Pnt> inner;
  switch (surface.GetType()) {
    case GeomAbs_Plane:
    case GeomAbs_Cylinder:
    case GeomAbs_Cone: break;
    case GeomAbs_Sphere: sphere_points(surface.Sphere(), inner); break;
    case GeomAbs_Torus: torus_points(surface.Torus(), inner); break;
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
  if (!inner.empty()) {
    // Shifted by whole periods into the face's range by the classifier.
    const BRepTopAdaptor_FClass2d classify(face, Precision::PConfusion());
    for (const gp_Pnt& p : inner) {
      double u = 0.0, v = 0.0;
      if (surface.GetType() == GeomAbs_Sphere)
        ElSLib::Parameters(surface.Sphere(), p, u, v);
      else
        ElSLib::Parameters(surface.Torus(), p, u, v);
      if (classify.Perform(gp_Pnt2d(u, v)) != TopAbs_OUT) box.Add(p);
    }
  }
  return to_box(box);
}

}  // namespace cooperage::occ::detail
