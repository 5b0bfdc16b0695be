#include "schemes/cooper/coincident_curves.h"

#include <Eigen/Geometry>

#include <cmath>
#include <set>

namespace cooperage::cooper {
namespace {

using P2 = Eigen::Vector2d;

std::vector<P2> projected(const CurveFact& c, const geom::Vec3& u, const geom::Vec3& v) {
  std::vector<P2> out;
  for (const geom::Vec3& x : c.samples) out.emplace_back(x.dot(u), x.dot(v));
  return out;
}

// Sample for sample, one way round or the other: the same geometry
// sampled at the same parameters (a B-spline copy of a circle is not seen,
// and keeps the behaviour without the row).
bool same_samples(const std::vector<P2>& a, const std::vector<P2>& b, double tol) {
  if (a.size() != b.size()) return false;
  bool forward = true, backward = true;
  for (size_t k = 0; k < a.size(); ++k) {
    forward = forward && (a[k] - b[k]).norm() <= tol;
    backward = backward && (a[k] - b[b.size() - 1 - k]).norm() <= tol;
  }
  return forward || backward;
}

}  // namespace

std::vector<std::pair<int, int>> coincident_cap_curves(const VolumeFacts& facts,
                                                       const std::vector<int>& caps,
                                                       const geom::Vec3& down) {
  const geom::Vec3 d = down.normalized();
  const geom::Vec3 e = std::abs(d.x()) > 0.6 ? geom::Vec3::UnitY() : geom::Vec3::UnitX();
  const geom::Vec3 u = (e - e.dot(d) * d).normalized();
  const geom::Vec3 v = d.cross(u);
  std::set<int> ids;
  for (int c : caps) {
    for (const auto& loop : facts.face(c)->loops) {
      for (const UseFact& use : loop) ids.insert(use.curve);
    }
  }
  std::vector<const CurveFact*> curves;
  std::vector<std::vector<P2>> lines;
  for (int id : ids) {
    curves.push_back(&facts.curves.at(id));
    lines.push_back(projected(*curves.back(), u, v));
  }
  const double tol = 1e-6 * facts.size();
  std::vector<std::pair<int, int>> out;
  for (size_t i = 0; i < curves.size(); ++i) {
    for (size_t j = i + 1; j < curves.size(); ++j) {
      if (same_samples(lines[i], lines[j], tol)) out.push_back({curves[i]->id, curves[j]->id});
    }
  }
  return out;
}

std::vector<IntervalRow> coincident_curve_rows(const std::vector<std::pair<int, int>>& pairs,
                                               const std::string& tag) {
  std::vector<IntervalRow> rows;
  for (const auto& [a, b] : pairs) {
    IntervalRow r;
    r.terms = {{a, 1}, {b, -1}};
    r.label = tag + ": curves " + std::to_string(a) + " and " + std::to_string(b) +
              " project onto each other along the sweep (their nodes seam)";
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace cooperage::cooper
