#include "schemes/cooper/coincident_curves.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <set>

namespace cooperage::cooper {
namespace {

using P2 = Eigen::Vector2d;

// Curved rims within this fraction of their spread project onto each other.
constexpr double kCurvedRimFraction = 0.05;

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

// The length over which segments p0p1 and q0q1 run on one line.
double shared_length(const P2& p0, const P2& p1, const P2& q0, const P2& q1, double tol) {
  const P2 d = p1 - p0;
  const double len = d.norm();
  if (!(len > 0)) return 0;
  const P2 t = d / len;
  auto off = [&](const P2& x) { return std::abs(t.x() * (x - p0).y() - t.y() * (x - p0).x()); };
  if (off(q0) > tol || off(q1) > tol) return 0;
  const double a = (q0 - p0).dot(t), b = (q1 - p0).dot(t);
  return std::max(0.0, std::min(len, std::max(a, b)) - std::max(0.0, std::min(a, b)));
}

// How far a projected curve spreads across its main direction (the root of
// the smaller principal variance of its samples): 0 for a straight edge,
// 0.71 r for a circle of radius r.
double spread(const std::vector<P2>& line) {
  if (line.size() < 3) return 0.0;
  P2 mean = P2::Zero();
  for (const P2& x : line) mean += x;
  mean /= static_cast<double>(line.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const P2& x : line) cov += (x - mean) * (x - mean).transpose();
  cov /= static_cast<double>(line.size());
  const double half_trace = 0.5 * cov.trace();
  const double det = cov.determinant();
  const double smaller = half_trace - std::sqrt(std::max(0.0, half_trace * half_trace - det));
  return std::sqrt(std::max(0.0, smaller));
}

struct Projected {
  std::vector<const CurveFact*> curves;
  std::vector<std::vector<P2>> lines;
  std::vector<Eigen::AlignedBox2d> boxes;  ///< each line's
};

Projected project_cap_curves(const VolumeFacts& facts, const std::vector<int>& caps,
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
  Projected out;
  for (int id : ids) {
    out.curves.push_back(&facts.curves.at(id));
    out.lines.push_back(projected(*out.curves.back(), u, v));
    Eigen::AlignedBox2d box;
    for (const P2& x : out.lines.back()) box.extend(x);
    out.boxes.push_back(box);
  }
  return out;
}

}  // namespace

std::vector<std::pair<int, int>> overlapping_cap_curves(const VolumeFacts& facts,
                                                        const std::vector<int>& caps,
                                                        const geom::Vec3& down) {
  const Projected p = project_cap_curves(facts, caps, down);
  const double tol = 1e-6 * facts.size();
  std::vector<std::pair<int, int>> out;
  for (size_t i = 0; i < p.curves.size(); ++i) {
    for (size_t j = i + 1; j < p.curves.size(); ++j) {
      const auto& a = p.lines[i];
      const auto& b = p.lines[j];
      // Segments share a length only where one passes within tol of the
      // other: lines whose boxes are farther apart share none (most pairs;
      // the pairs' segments were a twentieth of a refusal's search).
      if (p.boxes[i].exteriorDistance(p.boxes[j]) > tol) continue;
      if (same_samples(a, b, tol)) continue;
      double shared = 0;
      for (size_t k = 0; k + 1 < a.size(); ++k) {
        for (size_t m = 0; m + 1 < b.size(); ++m)
          shared += shared_length(a[k], a[k + 1], b[m], b[m + 1], tol);
      }
      if (shared > 1e-3 * std::min(p.curves[i]->length, p.curves[j]->length))
        out.push_back({p.curves[i]->id, p.curves[j]->id});
    }
  }
  return out;
}

std::vector<std::pair<int, int>> coincident_cap_curves(const VolumeFacts& facts,
                                                       const std::vector<int>& caps,
                                                       const geom::Vec3& down) {
  const Projected p = project_cap_curves(facts, caps, down);
  const double tol = 1e-6 * facts.size();
  std::vector<double> spreads;
  for (const auto& line : p.lines) spreads.push_back(spread(line));
  std::vector<std::pair<int, int>> out;
  for (size_t i = 0; i < p.curves.size(); ++i) {
    for (size_t j = i + 1; j < p.curves.size(); ++j) {
      // Curved rims a CAD model put a hair apart (coaxial blind holes from
      // both ends whose axes differ by 0.05 mm) seam too; straight edges
      // keep the tight tolerance (two long walls 1 apart are not one).
      const double near = std::max(tol, kCurvedRimFraction * std::min(spreads[i], spreads[j]));
      if (same_samples(p.lines[i], p.lines[j], near))
        out.push_back({p.curves[i]->id, p.curves[j]->id});
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
