#include "framework/intervals/sharp_corner_sizing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cooperage::intervals {
namespace {

using geom::Vec3;

/// A curve seen from one of its ends: the unit tangent leaving the vertex
/// and, once asked for (`curved`, an arc-length lookup: only at sharp
/// corners), the curvature vector there (towards the centre, 1 / radius
/// long) by the tangent's turn over a short arc.
struct End {
  const geom::Curve* curve = nullptr;
  bool at_start = true;
  Vec3 tangent = Vec3::Zero();
  Vec3 curvature = Vec3::Zero();
  bool valid = false;

  End(const geom::Curve& c, bool start) : curve(&c), at_start(start) {
    if (!c.geometry || !(c.length > 0)) return;
    const auto [t0, t1] = c.geometry->range();
    const Vec3 d0 = (at_start ? 1.0 : -1.0) * c.geometry->tangent(at_start ? t0 : t1);
    if (!(d0.norm() > 0)) return;
    tangent = d0.normalized();
    valid = true;
  }

  bool curved() {
    const double eps = 1e-3 * curve->length;
    const double s = at_start ? eps : curve->length - eps;
    const Vec3 d1 =
        (at_start ? 1.0 : -1.0) * curve->geometry->tangent(curve->geometry->parameter_at_length(s));
    if (!(d1.norm() > 0)) return false;
    curvature = (d1.normalized() - tangent) / eps;
    return true;
  }
};

/// How fast `mine`'s first chord closes the corner towards `other`: its
/// chord of length h leaves at h / 2 times the curvature off the tangent,
/// and the curvature's component towards `other` closes (negative: opens).
double closing_rate(const End& mine, const End& other) {
  Vec3 w = other.tangent - other.tangent.dot(mine.tangent) * mine.tangent;
  if (!(w.norm() > 1e-12)) return 0.0;
  return mine.curvature.dot(w.normalized());
}

}  // namespace

std::vector<EndSize> sharp_corner_sizes(const geom::Model& model,
                                        const std::function<double(int)>& size_of,
                                        const SharpCornerOptions& options) {
  const double max_angle = options.max_corner_deg * M_PI / 180.0;
  const double min_angle = options.min_corner_deg * M_PI / 180.0;
  std::vector<EndSize> out;
  for (const geom::Surface& surface : model.surfaces()) {
    for (const geom::Loop& loop : surface.loops) {
      const size_t n = loop.uses.size();
      if (n < 2) continue;
      for (size_t i = 0; i < n; ++i) {
        // The corner where use i ends and use i + 1 starts.
        const geom::CurveUse& in = loop.uses[i];
        const geom::CurveUse& on = loop.uses[(i + 1) % n];
        const bool in_at_start = in.sense != geom::Sense::Forward;
        const bool on_at_start = on.sense == geom::Sense::Forward;
        const geom::Curve& a = model.curve(in.curve);
        const geom::Curve& b = model.curve(on.curve);
        End ea(a, in_at_start), eb(b, on_at_start);
        if (!ea.valid || !eb.valid) continue;
        const double angle =
            std::atan2(ea.tangent.cross(eb.tangent).norm(), ea.tangent.dot(eb.tangent));
        if (!(angle <= max_angle) || !(angle >= min_angle)) continue;
        if (!ea.curved() || !eb.curved()) continue;
        // Both first intervals end up alike (the vertex's size grades both
        // curves), so their turns add: an arc opening the corner makes up
        // for one closing it (a pocket's arc and a hole's bending the same
        // way).
        const double closing = 0.5 * (closing_rate(ea, eb) + closing_rate(eb, ea));
        if (!(closing > 0)) continue;
        const double bound = options.share * angle / closing;
        for (const auto& [curve, at_start] :
             {std::pair{&a, in_at_start}, std::pair{&b, on_at_start}}) {
          const double size = size_of(curve->id);
          if (!(bound < size)) continue;
          out.push_back({curve->id, at_start, std::max(bound, options.min_fraction * size)});
        }
      }
    }
  }
  return out;
}

}  // namespace cooperage::intervals
