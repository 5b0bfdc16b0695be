// A solid's volume (Gauss integration over its faces), remembered per solid
// (same TShape and location) for the thread's later model builds: the import
// child computes it and sends it along, and the decomposition search builds
// a model for every candidate cut that leaves most solids as they were.
#include "framework/geometry/occ/detail.h"
#include "framework/geometry/occ/shape_memo.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <cmath>

namespace cooperage::occ::detail {
namespace {

using KnownVolumes = ShapeMemo<double, 5000>;

}  // namespace

void remember_solid_volume(const TopoDS_Shape& solid, double volume) {
  KnownVolumes::remember(solid, volume);
}

double solid_volume(const TopoDS_Shape& solid) {
  if (const double* v = KnownVolumes::find(solid)) return *v;
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props);
  const double volume = std::abs(props.Mass());
  remember_solid_volume(solid, volume);
  return volume;
}

}  // namespace cooperage::occ::detail
