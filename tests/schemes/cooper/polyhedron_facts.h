// VolumeFacts of a polyhedron written by hand (tests only, no CAD): faces
// as loops of 3D points -- the outer loop counter-clockwise seen from
// outside the volume, holes clockwise -- from which vertices (by position),
// straight curves (by vertex pair), corner angles, dihedral angles, normals
// and a submap verdict (single loop, corners turning by four quarter turns,
// none below 45 degrees or a REVERSAL) follow. Plain data in, plain data out.
#pragma once

#include "framework/scheme/vertex_angles.h"
#include "schemes/cooper/side_lattice.h"
#include "schemes/cooper/volume_facts.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

namespace cooperage::cooper::facts_test {

using geom::Vec3;
using PolyLoop = std::vector<Vec3>;
using PolyFace = std::vector<PolyLoop>;  // outer loop first

inline VolumeFacts polyhedron_facts(const std::vector<PolyFace>& faces) {
  constexpr double kPi = 3.14159265358979323846;
  VolumeFacts out;
  out.volume = 1;
  std::map<std::tuple<long, long, long>, int> vertex_of;
  auto vertex = [&](const Vec3& p) {
    const auto key = std::make_tuple(std::lround(p.x() * 1e6), std::lround(p.y() * 1e6),
                                     std::lround(p.z() * 1e6));
    auto it = vertex_of.find(key);
    if (it != vertex_of.end()) return it->second;
    const int id = static_cast<int>(vertex_of.size()) + 1;
    vertex_of[key] = id;
    out.vertices[id] = p;
    return id;
  };
  std::map<std::pair<int, int>, int> curve_of;
  std::map<int, std::vector<std::pair<int, bool>>> curve_uses;  // curve -> (face, forward)
  for (size_t f = 0; f < faces.size(); ++f) {
    FaceFact ff;
    ff.id = static_cast<int>(f) + 1;
    ff.planar = true;
    const PolyLoop& outer = faces[f].front();
    Vec3 n = Vec3::Zero();
    for (size_t k = 0; k < outer.size(); ++k) n += outer[k].cross(outer[(k + 1) % outer.size()]);
    ff.normal = n.normalized();
    ff.area = 0.5 * n.norm();
    Vec3 c = Vec3::Zero();
    for (const Vec3& p : outer) c += p / static_cast<double>(outer.size());
    ff.centre = c;
    ff.centroid = c;
    for (const PolyLoop& loop : faces[f]) {
      ff.loops.emplace_back();
      for (size_t k = 0; k < loop.size(); ++k) {
        const int a = vertex(loop[k]), b = vertex(loop[(k + 1) % loop.size()]);
        const auto key = std::make_pair(std::min(a, b), std::max(a, b));
        auto it = curve_of.find(key);
        if (it == curve_of.end()) {
          const int id = static_cast<int>(curve_of.size()) + 1;
          it = curve_of.emplace(key, id).first;
          CurveFact cf;
          cf.id = id;
          cf.start = key.first;
          cf.end = key.second;
          const Vec3 p0 = out.vertices.at(cf.start), p1 = out.vertices.at(cf.end);
          cf.length = (p1 - p0).norm();
          for (int s = 0; s <= 8; ++s) cf.samples.push_back(p0 + (p1 - p0) * (s / 8.0));
          out.curves[id] = cf;
        }
        const bool forward = a == key.first;
        ff.loops.back().push_back({it->second, forward});
        curve_uses[it->second].push_back({ff.id, forward});
      }
      if (&loop != &faces[f].front()) {
        Vec3 h = Vec3::Zero();
        for (size_t k = 0; k < loop.size(); ++k) h += loop[k].cross(loop[(k + 1) % loop.size()]);
        ff.area -= 0.5 * h.norm();
      }
    }
    if (faces[f].size() == 1) {
      int sum = 0;
      bool ok = true;
      for (size_t k = 0; k < outer.size(); ++k) {
        const Vec3 in = (outer[(k + outer.size() - 1) % outer.size()] - outer[k]).normalized();
        const Vec3 ou = (outer[(k + 1) % outer.size()] - outer[k]).normalized();
        double angle = std::acos(std::clamp(in.dot(ou), -1.0, 1.0)) * 180 / kPi;
        if (ou.cross(in).dot(ff.normal) < 0) angle = 360 - angle;  // re-entrant corner
        ff.angles.push_back(angle);
        const auto t = scheme::classify_angle(angle);
        ok = ok && t && *t != scheme::VertexType::Reversal;
        if (t) sum += static_cast<int>(*t);
      }
      ff.submappable = ok && sum == 4;
      ff.submap_score = ff.submappable ? 1.0 : 0.0;
      ff.submap_why = ff.submappable ? "" : "its corners do not make a submap";
    } else {
      ff.submap_why = "it has several loops";
    }
    type_corners(ff);
    out.faces.push_back(ff);
  }
  // Dihedral angles: the angle inside the volume at each curve of two faces.
  for (const auto& [curve, uses] : curve_uses) {
    if (uses.size() != 2) continue;
    const FaceFact& f = out.faces[static_cast<size_t>(uses[0].first - 1)];
    const FaceFact& g = out.faces[static_cast<size_t>(uses[1].first - 1)];
    const CurveFact& c = out.curves.at(curve);
    const Vec3 t = (out.vertices.at(c.end) - out.vertices.at(c.start)).normalized();
    // Directions into each face from the curve (the face lies left of its loop).
    const Vec3 df = f.normal.cross(uses[0].second ? t : Vec3(-t)).normalized();
    const Vec3 dg = g.normal.cross(uses[1].second ? t : Vec3(-t)).normalized();
    double angle = std::acos(std::clamp(df.dot(dg), -1.0, 1.0)) * 180 / kPi;
    if (dg.dot(f.normal) > 0) angle = 360 - angle;
    out.dihedral[curve] = angle;
  }
  return out;
}

/// `loop` turned to run counter-clockwise about `normal` (an outer loop),
/// or clockwise (`outer` false: a hole).
inline PolyLoop oriented(PolyLoop loop, const Vec3& normal, bool outer = true) {
  Vec3 n = Vec3::Zero();
  for (size_t k = 0; k < loop.size(); ++k) n += loop[k].cross(loop[(k + 1) % loop.size()]);
  if ((n.dot(normal) > 0) != outer) std::reverse(loop.begin(), loop.end());
  return loop;
}

/// The rectangle [x0, x1] x [y0, y1] at height z.
inline PolyLoop rect_xy(double x0, double y0, double x1, double y1, double z) {
  return {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
}

/// The four walls of the box [x0, x1] x [y0, y1] x [z0, z1], normals out of
/// it (`inward`: into it, the walls of a pocket).
inline std::vector<PolyFace> walls(double x0, double y0, double x1, double y1, double z0, double z1,
                                   bool inward = false) {
  const double s = inward ? -1 : 1;
  return {{oriented({{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, Vec3(0, -s, 0))},
          {oriented({{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, Vec3(s, 0, 0))},
          {oriented({{x1, y1, z0}, {x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}}, Vec3(0, s, 0))},
          {oriented({{x0, y1, z0}, {x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}}, Vec3(-s, 0, 0))}};
}

/// The unit cube: surfaces 1-4 its walls (y = 0, x = 1, y = 1, x = 0),
/// 5 its bottom, 6 its top.
inline std::vector<PolyFace> cube() {
  std::vector<PolyFace> f = walls(0, 0, 1, 1, 0, 1);
  f.push_back({oriented(rect_xy(0, 0, 1, 1, 0), Vec3(0, 0, -1))});
  f.push_back({oriented(rect_xy(0, 0, 1, 1, 1), Vec3(0, 0, 1))});
  return f;
}

/// A 4 x 4 x 2 block with a 2 x 2 pocket 1 deep from the top.
inline std::vector<PolyFace> pocket() {
  const Vec3 up(0, 0, 1);
  std::vector<PolyFace> f = walls(0, 0, 4, 4, 0, 2);
  f.push_back({oriented(rect_xy(0, 0, 4, 4, 0), -up)});
  f.push_back({oriented(rect_xy(0, 0, 4, 4, 2), up), oriented(rect_xy(1, 1, 3, 3, 2), up, false)});
  for (const PolyFace& w : walls(1, 1, 3, 3, 1, 2, true)) f.push_back(w);
  f.push_back({oriented(rect_xy(1, 1, 3, 3, 1), up)});
  return f;
}

}  // namespace cooperage::cooper::facts_test
