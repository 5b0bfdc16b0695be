#include "schemes/cooper/cap_dihedral.h"

#include "framework/core/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cooperage::cooper {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Sense of the first use of `curve` in the loops of `surface`.
geom::Sense use_sense(const geom::Surface& surface, int curve) {
  for (const auto& loop : surface.loops) {
    for (const auto& use : loop.uses) {
      if (use.curve == curve) return use.sense;
    }
  }
  throw MeshingError(ErrorCode::Internal, EntityRef::surface(surface.id),
                     "curve " + std::to_string(curve) + " is not in its loops");
}

}  // namespace

double cap_dihedral_degrees(const geom::Model& model, int volume_id, int cap, int side, int curve) {
  const geom::Curve& c = model.curve(curve);
  const geom::Surface& sc = model.surface(cap);
  const geom::Surface& ss = model.surface(side);
  const double cap_out = geom::sign(model.sense_in(cap, volume_id));
  const geom::Sense sense_c = use_sense(sc, curve);
  const geom::Sense sense_s = use_sense(ss, curve);
  const auto [t0, t1] = c.geometry->range();
  double worst = 0.0;
  for (double f : {0.25, 0.5, 0.75}) {
    const double t = t0 + f * (t1 - t0);
    const geom::Vec3 p = c.geometry->point(t);
    geom::Vec3 tangent = c.geometry->tangent(t);
    if (tangent.norm() == 0) continue;
    tangent.normalize();
    const auto pc = sc.geometry->project(p);
    const auto ps = ss.geometry->project(p);
    const geom::Vec3 dc = pc.normal.cross(geom::sign(sense_c) * tangent).normalized();
    const geom::Vec3 ds = ps.normal.cross(geom::sign(sense_s) * tangent).normalized();
    const geom::Vec3 cap_outward = cap_out * pc.normal;
    double angle = std::acos(std::clamp(dc.dot(ds), -1.0, 1.0)) * 180.0 / kPi;
    if (ds.dot(cap_outward) > 0) angle = 360.0 - angle;
    worst = std::max(worst, angle);
  }
  return worst;
}

}  // namespace cooperage::cooper
