// A solid's volume (Gauss integration over its faces), remembered per solid
// (same TShape and location) for the thread's later model builds: the import
// child computes it and sends it along, and the decomposition search builds
// a model for every candidate cut that leaves most solids as they were.
// The pieces of a cut are new solids, but most of their faces are the
// solid's own: the volume is the sum of its faces' terms (the divergence
// theorem), each remembered per face, so a piece integrates only the faces
// the cut made (13 % of a refusal's search, gmsh_Kurbelwelle, issue 16).
#include "framework/geometry/occ/detail.h"
#include "framework/geometry/occ/shape_memo.h"

#include <BRepGProp_Domain.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp_Vinert.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>

#include <cmath>

namespace cooperage::occ::detail {
namespace {

using KnownVolumes = ShapeMemo<double, 5000>;
/// A face's term, oriented as the face is stored (FORWARD).
using KnownFaceTerms = ShapeMemo<double, 20000>;

// The face's term of the volume of a solid it bounds with its orientation:
// the integral of x . n / 3 over it, about the origin (one point for every
// face; BRepGProp takes the solid's rough centre, which is not a face's).
double face_term(const TopoDS_Face& face) {
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  double term = 0.0;
  if (const double* known = KnownFaceTerms::find(forward)) {
    term = *known;
  } else {
    BRepGProp_Face surface(forward);
    BRepGProp_Vinert integral;
    integral.SetLocation(gp_Pnt(0, 0, 0));
    if (surface.NaturalRestriction()) {
      integral.Perform(surface);
    } else {
      BRepGProp_Domain domain(forward);
      integral.Perform(surface, domain);
    }
    term = integral.Mass();
    KnownFaceTerms::remember(forward, term);
  }
  return face.Orientation() == TopAbs_REVERSED ? -term : term;
}

}  // namespace

void remember_solid_volume(const TopoDS_Shape& solid, double volume) {
  KnownVolumes::remember(solid, volume);
}

double solid_volume(const TopoDS_Shape& solid) {
  if (const double* v = KnownVolumes::find(solid)) return *v;
  double sum = 0.0;
  for (TopExp_Explorer ex(solid, TopAbs_FACE); ex.More(); ex.Next()) {
    const TopAbs_Orientation o = ex.Current().Orientation();
    if (o == TopAbs_FORWARD || o == TopAbs_REVERSED) sum += face_term(TopoDS::Face(ex.Current()));
  }
  const double volume = std::abs(sum);
  remember_solid_volume(solid, volume);
  return volume;
}

}  // namespace cooperage::occ::detail
