// A solid's volume (Gauss integration over its faces), remembered per solid
// (same TShape and location) for the thread's later model builds: the import
// child computes it and sends it along, and the decomposition search builds
// a model for every candidate cut that leaves most solids as they were.
#include "framework/geometry/occ/detail.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <NCollection_DataMap.hxx>
#include <TopTools_ShapeMapHasher.hxx>

#include <cmath>

namespace cooperage::occ::detail {
namespace {

// Holding the solid keeps its TShape alive, so a key is never reused by
// another solid. Bounded: cleared when it grows past kMaxSolids.
constexpr int kMaxSolids = 5000;

using VolumeBySolid = NCollection_DataMap<TopoDS_Shape, double, TopTools_ShapeMapHasher>;

VolumeBySolid& known_volumes() {
  thread_local VolumeBySolid known;
  return known;
}

}  // namespace

void remember_solid_volume(const TopoDS_Shape& solid, double volume) {
  VolumeBySolid& known = known_volumes();
  if (known.Extent() >= kMaxSolids) known.Clear();
  known.Bind(solid, volume);
}

double solid_volume(const TopoDS_Shape& solid) {
  if (const double* v = known_volumes().Seek(solid)) return *v;
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props);
  const double volume = std::abs(props.Mass());
  remember_solid_volume(solid, volume);
  return volume;
}

}  // namespace cooperage::occ::detail
