#include "framework/intervals/sharp_corner_sizing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cooperage::intervals {
namespace {

using geom::Vec3;

/// A curve seen from one of its ends: the unit tangent leaving the vertex
/// and the curvature vector there (towards the centre, 1 / radius long),
/// by the tangent's turn over a short arc.
struct End {
  Vec3 tangent = Vec3::Zero();
  Vec3 curvature = Vec3::Zero();
  bool valid = false;
};

End end_of(const geom::Curve& curve, bool at_start) {
  End out;
  if (!curve.geometry || !(curve.length > 0)) return out;
  const auto [t0, t1] = curve.geometry->range();
  const double sign = at_start ? 1.0 : -1.0;
  const Vec3 d0 = sign * curve.geometry->tangent(at_start ? t0 : t1);
  const double eps = 1e-3 * curve.length;
  const double s = at_start ? eps : curve.length - eps;
  const Vec3 d1 = sign * curve.geometry->tangent(curve.geometry->parameter_at_length(s));
  if (!(d0.norm() > 0) || !(d1.norm() > 0)) return out;
  out.tangent = d0.normalized();
  out.curvature = (d1.normalized() - out.tangent) / eps;
  out.valid = true;
  return out;
}

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
        const End ea = end_of(a, in_at_start);
        const End eb = end_of(b, on_at_start);
        if (!ea.valid || !eb.valid) continue;
        const double angle =
            std::atan2(ea.tangent.cross(eb.tangent).norm(), ea.tangent.dot(eb.tangent));
        if (!(angle <= max_angle) || !(angle >= min_angle)) continue;
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
