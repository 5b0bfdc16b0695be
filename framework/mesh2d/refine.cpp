#include "framework/mesh2d/refine.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace cooperage::mesh2d::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Relative margin of every threshold test, so that exact ties of symmetric
// inputs (a right triangle's circumcentre on a segment's diametral circle)
// are decided alike for a rigidly moved input.
constexpr double kTie = 1e-9;
constexpr double kEncroachCos = -0.5;

class Refiner {
 public:
  Refiner(Cdt& cdt, const RefineOptions& options, std::size_t max_points)
      : cdt_(cdt),
        sin_min_(std::sin(options.min_angle_deg * kPi / 180.0)),
        size_factor_(options.size_factor * options.size_scale),
        max_points_(max_points) {}

  RefineStats run() {
    for (size_t t = 0; t < cdt_.tris.size(); ++t) push(static_cast<int>(t));
    while (!queue_.empty()) {
      const auto [t, stamp] = queue_.front();
      queue_.pop_front();
      const Tri& T = cdt_.tris[static_cast<size_t>(t)];
      if (T.stamp != stamp || !bad(t)) continue;
      if (cdt_.pts.size() >= max_points_) {
        stats_.capped = true;
        break;
      }
      cdt_.touched.clear();
      if (!split(t)) {
        ++stats_.rejected;
        continue;
      }
      for (int u : cdt_.touched) push(u);
    }
    return stats_;
  }

 private:
  const Point2& P(int v) const { return cdt_.pts[static_cast<size_t>(v)]; }

  void push(int t) {
    const Tri& T = cdt_.tris[static_cast<size_t>(t)];
    if (T.inside && bad(t)) queue_.emplace_back(t, T.stamp);
  }

  // Skinny (smallest angle below the bound) or larger than the local size.
  bool bad(int t) const {
    const Tri& T = cdt_.tris[static_cast<size_t>(t)];
    if (!T.inside) return false;
    const Point2& a = P(T.v[0]);
    const Point2& b = P(T.v[1]);
    const Point2& c = P(T.v[2]);
    const double l0 = (c - b).squaredNorm();
    const double l1 = (a - c).squaredNorm();
    const double l2 = (b - a).squaredNorm();
    const double h =
        (cdt_.size[static_cast<size_t>(T.v[0])] + cdt_.size[static_cast<size_t>(T.v[1])] +
         cdt_.size[static_cast<size_t>(T.v[2])]) /
        3.0 * size_factor_;
    const double lmax = std::max(l0, std::max(l1, l2));
    if (lmax > h * h * (1.0 + kTie)) return true;
    // Smallest angle: opposite the shortest edge; sin = 2 area / product of the others.
    int s = 0;
    if (l1 < l0 && l1 <= l2)
      s = 1;
    else if (l2 < l0 && l2 < l1)
      s = 2;
    const double area2 = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    const double others = s == 0 ? l1 * l2 : (s == 1 ? l0 * l2 : l0 * l1);
    if (area2 * area2 >= sin_min_ * sin_min_ * others * (1.0 - kTie)) return false;
    // A small angle between two constraints is input; refining cannot fix it.
    const bool c1 = T.c[static_cast<size_t>(nxt(s))];
    const bool c2 = T.c[static_cast<size_t>(prv(s))];
    return !(c1 && c2);
  }

  static Point2 circumcentre(const Point2& a, const Point2& b, const Point2& c) {
    const Point2 ba = b - a;
    const Point2 ca = c - a;
    const double d = 2.0 * (ba.x() * ca.y() - ba.y() * ca.x());
    const double b2 = ba.squaredNorm();
    const double c2 = ca.squaredNorm();
    return a + Point2((ca.y() * b2 - ba.y() * c2) / d, (ba.x() * c2 - ca.x() * b2) / d);
  }

  // The triangles whose circumcircle holds p, reachable from loc.tri without
  // crossing constraints. Reports the first encroached constraint (t, i),
  // and the distance from p to the nearest cavity vertex.
  struct Cavity {
    int enc_tri = -1;
    int enc_edge = -1;
    double nearest = 0.0;
  };
  Cavity scan(const Point2& p, int start) {
    Cavity out;
    out.nearest = std::numeric_limits<double>::infinity();
    ++mark_;
    if (seen_.size() < cdt_.tris.size()) seen_.resize(cdt_.tris.size(), 0);
    stack_.clear();
    stack_.push_back(start);
    seen_[static_cast<size_t>(start)] = mark_;
    while (!stack_.empty()) {
      const int t = stack_.back();
      stack_.pop_back();
      const Tri& T = cdt_.tris[static_cast<size_t>(t)];
      for (int i = 0; i < 3; ++i) {
        out.nearest = std::min(out.nearest, (P(T.v[static_cast<size_t>(i)]) - p).norm());
        const Point2& a = P(T.v[static_cast<size_t>(nxt(i))]);
        const Point2& b = P(T.v[static_cast<size_t>(prv(i))]);
        if (T.c[static_cast<size_t>(i)]) {
          const double cosine =
              (a - p).dot(b - p) / std::sqrt((a - p).squaredNorm() * (b - p).squaredNorm());
          if (out.enc_tri < 0 && cosine < kEncroachCos - kTie) {
            out.enc_tri = t;
            out.enc_edge = i;
          }
          continue;
        }
        const int u = T.n[static_cast<size_t>(i)];
        if (u < 0 || seen_[static_cast<size_t>(u)] == mark_) continue;
        const Tri& U = cdt_.tris[static_cast<size_t>(u)];
        if (!U.inside) continue;
        double perm = 0.0;
        if (incircle_fast(P(U.v[0]), P(U.v[1]), P(U.v[2]), p, perm) > kDelaunayTieTol * perm) {
          seen_[static_cast<size_t>(u)] = mark_;
          stack_.push_back(u);
        }
      }
    }
    return out;
  }

  // Linear interpolation of the size field at p over triangle loc.tri.
  double size_at(const Point2& p, int t) const {
    const Tri& T = cdt_.tris[static_cast<size_t>(t)];
    const Point2& a = P(T.v[0]);
    const Point2& b = P(T.v[1]);
    const Point2& c = P(T.v[2]);
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    double w0 = ((b - p).x() * (c - p).y() - (b - p).y() * (c - p).x()) / area;
    double w1 = ((c - p).x() * (a - p).y() - (c - p).y() * (a - p).x()) / area;
    w0 = std::clamp(w0, 0.0, 1.0);
    w1 = std::clamp(w1, 0.0, 1.0 - w0);
    const double w2 = 1.0 - w0 - w1;
    return w0 * cdt_.size[static_cast<size_t>(T.v[0])] +
           w1 * cdt_.size[static_cast<size_t>(T.v[1])] +
           w2 * cdt_.size[static_cast<size_t>(T.v[2])];
  }

  bool insert_at(const Point2& p, const Cdt::Location& loc) {
    const int v = cdt_.add_point(p, size_at(p, loc.tri));
    if (cdt_.insert(v, loc)) return true;
    cdt_.pts.pop_back();
    cdt_.size.pop_back();
    cdt_.vtri.pop_back();
    return false;
  }

  bool split(int t) {
    const Tri& T = cdt_.tris[static_cast<size_t>(t)];
    const Point2& a = P(T.v[0]);
    const Point2& b = P(T.v[1]);
    const Point2& c = P(T.v[2]);
    const double shortest = std::sqrt(
        std::min((b - a).squaredNorm(), std::min((c - b).squaredNorm(), (a - c).squaredNorm())));
    const Point2 cc = circumcentre(a, b, c);
    if (!std::isfinite(cc.x()) || !std::isfinite(cc.y())) return false;
    const Cdt::Location loc = cdt_.locate(cc, t, true);
    if (loc.where == Cdt::Where::Blocked) return apex(loc.tri, loc.edge);
    if (loc.where != Cdt::Where::Inside && loc.where != Cdt::Where::OnEdge) return false;
    if (loc.where == Cdt::Where::OnEdge &&
        cdt_.tris[static_cast<size_t>(loc.tri)].c[static_cast<size_t>(loc.edge)]) {
      return apex(loc.tri, loc.edge);
    }
    const Cavity cav = scan(cc, loc.tri);
    if (cav.enc_tri >= 0) return apex(cav.enc_tri, cav.enc_edge);
    if (cav.nearest < 0.25 * shortest) return false;
    return insert_at(cc, loc);
  }

  // Ruppert splits an encroached segment; ours are fixed, so try the apex of
  // the equilateral triangle on the segment, on the domain side, instead.
  bool apex(int t, int i) {
    const Tri& T = cdt_.tris[static_cast<size_t>(t)];
    if (!T.inside) return false;
    const Point2& a = P(T.v[static_cast<size_t>(nxt(i))]);
    const Point2& b = P(T.v[static_cast<size_t>(prv(i))]);
    const Point2 d = b - a;
    const double len = d.norm();
    const Point2 p = 0.5 * (a + b) + Point2(-d.y(), d.x()) * (0.5 * std::sqrt(3.0));
    const Cdt::Location loc = cdt_.locate(p, t, true);
    if (loc.where != Cdt::Where::Inside && loc.where != Cdt::Where::OnEdge) return false;
    if (loc.where == Cdt::Where::OnEdge &&
        cdt_.tris[static_cast<size_t>(loc.tri)].c[static_cast<size_t>(loc.edge)]) {
      return false;
    }
    const Cavity cav = scan(p, loc.tri);
    if (cav.enc_tri >= 0 || cav.nearest < 0.5 * len) return false;
    return insert_at(p, loc);
  }

  Cdt& cdt_;
  double sin_min_;
  double size_factor_;
  std::size_t max_points_;
  std::deque<std::pair<int, std::uint32_t>> queue_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t mark_ = 0;
  std::vector<int> stack_;
  RefineStats stats_;
};

}  // namespace

RefineStats refine(Cdt& cdt, const RefineOptions& options, std::size_t max_points) {
  return Refiner(cdt, options, max_points).run();
}

}  // namespace cooperage::mesh2d::detail
