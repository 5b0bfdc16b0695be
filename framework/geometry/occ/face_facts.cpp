// The area, area centroid and tight bounding box of a face, remembered per face (same
// TShape and location) for the thread's later model builds: the
// decomposition search builds a model for every candidate cut, and a cut
// leaves most faces as they were. The tight box (face_box.cpp; before it
// BRepBndLib::AddOptimal, a particle swarm over the surface) was a fifth of
// a refused screw's search, and a quarter of a B-spline part's run in 2D,
// computed once in the import child and once again in the parent until the
// child sent its facts along.
#include "framework/geometry/occ/detail.h"
#include "framework/geometry/occ/shape_memo.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <cmath>

namespace cooperage::occ::detail {
namespace {

using KnownFacts = ShapeMemo<FaceFacts, 20000>;

}  // namespace

void remember_face_facts(const TopoDS_Face& face, const FaceFacts& facts) {
  KnownFacts::remember(face, facts);
}

FaceFacts face_facts(const TopoDS_Face& face) {
  if (const FaceFacts* f = KnownFacts::find(face)) return *f;
  FaceFacts out;
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  out.area = std::abs(props.Mass());
  if (out.area > 0) {
    const gp_Pnt c = props.CentreOfMass();
    out.centroid = Vec3(c.X(), c.Y(), c.Z());
  }
  out.box = tight_face_box(face);
  remember_face_facts(face, out);
  return out;
}

}  // namespace cooperage::occ::detail
