#include "framework/decompose/volume_samples.h"

#include <algorithm>
#include <set>

namespace cooperage::decompose {

std::vector<int> curves_of(const geom::Model& model, int volume) {
  std::set<int> curves;
  for (int s : model.surfaces_of(volume)) {
    for (const geom::Loop& loop : model.surface(s).loops) {
      for (const geom::CurveUse& use : loop.uses) curves.insert(use.curve);
    }
  }
  return {curves.begin(), curves.end()};
}

std::vector<geom::Vec3> outward_normals_at(const geom::Model& model, int volume, int c) {
  const geom::Curve& curve = model.curve(c);
  const auto [t0, t1] = curve.geometry->range();
  const geom::Vec3 mid = curve.geometry->point(0.5 * (t0 + t1));
  std::vector<geom::Vec3> normals;
  for (int s : curve.surfaces) {
    const auto& vols = model.surface(s).volumes;
    if (std::find(vols.begin(), vols.end(), volume) == vols.end()) continue;
    normals.push_back(geom::sign(model.sense_in(s, volume)) *
                      model.surface(s).geometry->project(mid).normal.normalized());
  }
  return normals;
}

std::vector<geom::Vec3> volume_samples(const geom::Model& model, int volume, int per_curve) {
  const std::vector<int> curves = curves_of(model, volume);
  std::set<int> vertices;
  for (int c : curves) {
    vertices.insert(model.curve(c).start_vertex);
    vertices.insert(model.curve(c).end_vertex);
  }
  std::vector<geom::Vec3> out;
  for (int v : vertices) out.push_back(model.vertex(v).point);
  for (int c : curves) {
    const auto& g = *model.curve(c).geometry;
    const auto [t0, t1] = g.range();
    for (int k = 1; k <= per_curve; ++k)
      out.push_back(g.point(t0 + (t1 - t0) * k / (per_curve + 1)));
  }
  return out;
}

}  // namespace cooperage::decompose
