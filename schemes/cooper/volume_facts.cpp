#include "schemes/cooper/volume_facts.h"

#include "framework/scheme/vertex_angles.h"
#include "schemes/cooper/cap_dihedral.h"
#include "schemes/cooper/side_lattice.h"

#include <algorithm>
#include <set>

namespace cooperage::cooper {

const FaceFact* VolumeFacts::face(int id) const {
  const auto it = std::lower_bound(faces.begin(), faces.end(), id,
                                   [](const FaceFact& f, int i) { return f.id < i; });
  return it != faces.end() && it->id == id ? &*it : nullptr;
}

std::vector<int> VolumeFacts::faces_of_curve(int curve) const {
  std::vector<int> out;
  for (const FaceFact& f : faces) {
    bool uses = false;
    for (const auto& loop : f.loops) {
      for (const UseFact& u : loop) uses = uses || u.curve == curve;
    }
    if (uses) out.push_back(f.id);
  }
  return out;
}

double VolumeFacts::extent(const std::vector<int>& curve_ids) const {
  geom::Vec3 lo = geom::Vec3::Constant(1e300), hi = geom::Vec3::Constant(-1e300);
  for (int id : curve_ids) {
    for (const geom::Vec3& p : curves.at(id).samples) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  return hi.x() >= lo.x() ? (hi - lo).norm() : 0.0;
}

double VolumeFacts::size() const { return known_size > 0 ? known_size : span(); }

double VolumeFacts::span() const {
  // The span of the vertices and curve samples, which a rigid motion keeps
  // (the box's diagonal grew by up to 1.7 when a part was turned, and a
  // 0.01 step between two floors was a level or not by the tolerance
  // derived from it: campaign seed 5 case 176): from the first vertex the
  // farthest point, from that the farthest again, while the distance grows.
  // A box-shaped part gets its box's diagonal, as before.
  std::vector<geom::Vec3> points;
  for (const auto& [id, p] : vertices) points.push_back(p);
  for (const auto& [id, c] : curves)
    points.insert(points.end(), c.samples.begin(), c.samples.end());
  if (points.empty()) return 1.0;
  auto farthest = [&](const geom::Vec3& from) {
    size_t best = 0;
    double d2 = -1;
    for (size_t i = 0; i < points.size(); ++i) {
      const double e = (points[i] - from).squaredNorm();
      if (e > d2) {
        d2 = e;
        best = i;
      }
    }
    return std::make_pair(best, std::sqrt(d2));
  };
  size_t at = 0;
  double span = 0;
  for (int round = 0; round < 4; ++round) {
    const auto [next, d] = farthest(points[at]);
    if (!(d > span)) break;
    span = d;
    at = next;
  }
  return span > 0 ? span : 1.0;
}

VolumeFacts gather_facts(const geom::Model& model, int volume_id, const scheme::Registry& registry,
                         const scheme::Settings* settings) {
  VolumeFacts out;
  out.volume = volume_id;
  out.shells = static_cast<int>(model.volume(volume_id).shells.size());
  std::vector<int> ids = model.surfaces_of(volume_id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const scheme::SurfaceScheme* submap = registry.surface_scheme("submap");
  std::map<int, std::set<int>> curve_faces;
  for (int id : ids) {
    const geom::Surface& s = model.surface(id);
    FaceFact f;
    f.id = id;
    f.planar = s.geometry->type() == geom::SurfaceType::Plane;
    f.area = s.area;
    for (int v : s.volumes) f.other_volumes += v != volume_id && v != 0 ? 1 : 0;
    // Near the area centroid, which moves with the face: the box centre of
    // a hole's wall cut open by a pocket lay near its axis, where every
    // point of the wall is nearly nearest, and the projection picked one by
    // rounding; a turned part found the wall facing the other way in
    // slab_regions (campaign seed 4 case 15: refused unless turned).
    f.centroid = s.centroid ? *s.centroid : 0.5 * (s.box.min + s.box.max);
    const auto at = s.geometry->project(f.centroid);
    f.centre = at.point;
    f.normal = geom::sign(model.sense_in(id, volume_id)) * at.normal.normalized();
    for (const auto& loop : s.loops) {
      f.loops.emplace_back();
      for (const auto& use : loop.uses) {
        f.loops.back().push_back({use.curve, use.sense == geom::Sense::Forward});
        curve_faces[use.curve].insert(id);
      }
    }
    if (s.loops.size() == 1) {
      for (const auto& corner : scheme::loop_corners(model, id, 0))
        f.angles.push_back(corner.angle);
      if (submap) {
        const scheme::Applicability a =
            submap->applicable(scheme::SurfaceView{model, id, nullptr, settings});
        f.submappable = a.ok;
        f.submap_score = a.score;
        f.submap_why = a.why;
      } else {
        f.submap_why = "the submap scheme is not registered";
      }
    } else {
      f.submap_why = "it has " + std::to_string(s.loops.size()) + " loops; a side face needs one";
    }
    type_corners(f);
    out.faces.push_back(std::move(f));
  }
  for (const auto& [curve, faces] : curve_faces) {
    const geom::Curve& c = model.curve(curve);
    CurveFact cf;
    cf.id = curve;
    cf.start = c.start_vertex;
    cf.end = c.end_vertex;
    cf.length = c.length;
    const auto [t0, t1] = c.geometry->range();
    constexpr int kSamples = 16;
    for (int k = 0; k <= kSamples; ++k)
      cf.samples.push_back(c.geometry->point(t0 + (t1 - t0) * k / kSamples));
    out.curves[curve] = std::move(cf);
    for (int v : {c.start_vertex, c.end_vertex}) out.vertices[v] = model.vertex(v).point;
    if (faces.size() == 2) {
      const int a = *faces.begin(), b = *faces.rbegin();
      const double angle = cap_dihedral_degrees(model, volume_id, a, b, curve);
      out.dihedral[curve] = angle;
      if (angle >= kMaxCapDihedral && angle <= kReentrantMin) {
        for (const auto& [f, g] : {std::pair{a, b}, std::pair{b, a}}) {
          for (TangentDeparture& d : tangent_departures(model, volume_id, curve, f, g))
            out.departures.push_back(d);
        }
      }
    }
  }
  out.known_size = out.span();
  return out;
}

}  // namespace cooperage::cooper
