#include "schemes/pave/frontal_fill.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace cooperage::pave::detail {
namespace {

using cdt::Cdt;
using cdt::Tri;
using V2 = Eigen::Vector2d;

/// Circumradius (infinite for a degenerate or clockwise triangle).
double circumradius(const V2& a, const V2& b, const V2& c) {
  V2 offset;
  return cdt::circumcentre_offset(a, b, c, offset) ? offset.norm() : INFINITY;
}

}  // namespace

int frontal_fill(Cdt& cdt, const std::vector<std::vector<int>>& loops, double accept_radius) {
  // The lattice frame of every point as (cos 4t, sin 4t) of its angle t
  // (a cross: defined modulo 90 degrees): on the loops the mean of the two
  // loop edges' directions, for a new point the mean of its front edge's.
  std::vector<V2> frame(cdt.p.size(), V2(1, 0));
  auto cross_of = [](const V2& d) {
    const double t = 4.0 * std::atan2(d.y(), d.x());
    return V2(std::cos(t), std::sin(t));
  };
  auto mean_cross = [](const V2& f, const V2& g) {
    const V2 m = f + g;
    return m.norm() > 1e-6 ? V2(m.normalized()) : f;
  };
  for (const auto& loop : loops) {
    for (size_t k = 0; k < loop.size(); ++k) {
      const V2 p = cdt.pt(loop[k]);
      const V2 prev = cdt.pt(loop[(k + loop.size() - 1) % loop.size()]);
      const V2 next = cdt.pt(loop[(k + 1) % loop.size()]);
      frame[static_cast<size_t>(loop[k])] = mean_cross(cross_of(p - prev), cross_of(next - p));
    }
  }
  // Sizes of new points: linear over the triangulation of the loop points
  // alone (a background mesh), so that sizes grade between loops instead of
  // being carried along by the rows. Each point remembers its background
  // triangle as the start of the next walk.
  Cdt background = cdt;
  std::vector<int> home(cdt.p.size(), -1);
  for (int i = 0; i < static_cast<int>(background.t.size()); ++i) {
    const Tri& T = background.tri(i);
    if (!T.alive || !T.inside) continue;
    for (int v : T.v) home[static_cast<size_t>(v)] = i;
  }
  auto size_at = [&](const V2& x, int near, int& found) {
    found = -1;
    const int start = home[static_cast<size_t>(near)];
    if (start < 0) return cdt.size[static_cast<size_t>(near)];
    const int loc = background.locate(x, start, false);
    if (loc < 0 || !background.tri(loc).inside) return cdt.size[static_cast<size_t>(near)];
    found = loc;
    const Tri& T = background.tri(loc);
    const V2 a = background.pt(T.v[0]), b = background.pt(T.v[1]), c = background.pt(T.v[2]);
    const double area = cdt::orient(a, b, c);
    if (!(area > 0)) return cdt.size[static_cast<size_t>(near)];
    const double wa = cdt::orient(x, b, c) / area, wb = cdt::orient(a, x, c) / area;
    const double wc = 1.0 - wa - wb;
    return wa * background.size[static_cast<size_t>(T.v[0])] +
           wb * background.size[static_cast<size_t>(T.v[1])] +
           wc * background.size[static_cast<size_t>(T.v[2])];
  };
  auto accepted = [&](int ti) {
    const Tri& T = cdt.tri(ti);
    return circumradius(cdt.pt(T.v[0]), cdt.pt(T.v[1]), cdt.pt(T.v[2])) <=
           accept_radius * cdt.mean_size(T);
  };
  auto live_inside = [&](int ti) { return ti >= 0 && cdt.tri(ti).alive && cdt.tri(ti).inside; };

  std::vector<int> queue;
  for (int i = 0; i < static_cast<int>(cdt.t.size()); ++i) {
    if (live_inside(i) && !accepted(i)) queue.push_back(i);
  }
  // A triangle whose point was refused is left to the refinement; slots of
  // dead triangles are recycled, so the flag is cleared for new ones.
  std::vector<char> frozen(cdt.t.size(), 0);
  int inserted = 0;
  for (size_t head = 0; head < queue.size(); ++head) {
    const int ti = queue[head];
    if (!live_inside(ti) || frozen[static_cast<size_t>(ti)] || accepted(ti)) continue;
    const Tri T = cdt.tri(ti);
    // The front edge: a loop edge first, else an edge to an accepted triangle.
    int front = -1;
    for (int i = 0; i < 3 && front < 0; ++i) {
      if (T.c[static_cast<size_t>(i)]) front = i;
    }
    for (int i = 0; i < 3 && front < 0; ++i) {
      const int nb = T.n[static_cast<size_t>(i)];
      if (live_inside(nb) && accepted(nb)) front = i;
    }
    if (front < 0) continue;  // queued again when a neighbour is accepted
    const int a = T.v[static_cast<size_t>((front + 1) % 3)],
              b = T.v[static_cast<size_t>((front + 2) % 3)];
    const V2 pa = cdt.pt(a), pb = cdt.pt(b);
    const double len = (pb - pa).norm();
    if (!(len > 0)) continue;
    const V2 n = V2(-(pb - pa).y(), (pb - pa).x()) / len;
    int unused = -1;
    const double h = size_at(0.5 * (pa + pb) + 0.5 * len * n, a, unused);

    std::array<V2, 2> candidates;
    size_t count = 0;
    const V2 cross = mean_cross(frame[static_cast<size_t>(a)], frame[static_cast<size_t>(b)]);
    const double angle = 0.25 * std::atan2(cross.y(), cross.x());
    const V2 u(std::cos(angle), std::sin(angle)), v(-u.y(), u.x());
    const V2 d = pb - pa;
    const double du = d.dot(u), dv = d.dot(v);
    // The front edge against the frame: along an axis (a leg) or across
    // (a diagonal, within 22.5 degrees of 45); loop edges are legs.
    const double phi = std::atan2(std::abs(dv), std::abs(du));
    const bool diagonal = !T.c[static_cast<size_t>(front)] && phi > M_PI / 8 && phi < 3 * M_PI / 8;
    if (diagonal) {
      // The lattice point that makes the edge a hypotenuse, on T's side.
      const V2 x1 = pa + du * u, x2 = pa + dv * v;
      candidates[count++] = cdt::orient(pa, pb, x1) > 0 ? x1 : x2;
    } else {
      // A leg: one size along the frame axis nearest the edge's normal
      // (the edge's own normal on a loop edge), at the endpoint whose
      // perpendicular point has more room first.
      V2 up = n;
      if (!T.c[static_cast<size_t>(front)]) {
        up = std::abs(n.dot(u)) > std::abs(n.dot(v)) ? u : v;
        if (up.dot(n) < 0) up = -up;
      }
      const V2 xa = pa + h * up, xb = pb + h * up;
      auto clearance = [&](const V2& x) {
        double dist = INFINITY;
        for (size_t k = 0; k < 3; ++k) {
          dist = std::min(dist, (cdt.pt(T.v[k]) - x).squaredNorm());
          const int nb = T.n[k];
          if (nb < 0) continue;
          for (int w : cdt.tri(nb).v) dist = std::min(dist, (cdt.pt(w) - x).squaredNorm());
        }
        return dist;
      };
      const bool a_first = clearance(xa) >= clearance(xb);
      candidates[count++] = a_first ? xa : xb;
      candidates[count++] = a_first ? xb : xa;
    }

    bool done = false;
    for (size_t k = 0; k < count && !done; ++k) {
      const V2 x = candidates[k];
      // A point outside T's circumcircle would leave T as it is (a point
      // inside may still, through a constrained or shrunk cavity; T is then
      // left to the refinement).
      if (!(cdt::incircle(cdt.pt(T.v[0]), cdt.pt(T.v[1]), cdt.pt(T.v[2]), x) > 0)) continue;
      const int loc = cdt.locate(x, ti, true);
      if (loc < 0 || !cdt.tri(loc).inside) continue;
      const int pi = static_cast<int>(cdt.p.size());
      int where = -1;
      const double hx = size_at(x, a, where);
      cdt.p.push_back(x);
      cdt.size.push_back(hx);
      cdt.vt.push_back(-1);
      if (!cdt.insert(pi, loc, true, 0.55 * std::min(h, hx))) {
        cdt.p.pop_back();
        cdt.size.pop_back();
        cdt.vt.pop_back();
        continue;
      }
      home.push_back(where >= 0 ? where
                                : home[static_cast<size_t>(a)]);  // a walk's start, at worst near
      frame.push_back(cross);
      done = true;
    }
    if (!done) {
      frozen[static_cast<size_t>(ti)] = 1;
      continue;
    }
    ++inserted;
    if (frozen.size() < cdt.t.size()) frozen.resize(cdt.t.size(), 0);
    for (int c : cdt.created) {
      frozen[static_cast<size_t>(c)] = 0;
      if (!accepted(c)) {
        queue.push_back(c);
        continue;
      }
      for (int nb : cdt.tri(c).n) {
        if (live_inside(nb) && !accepted(nb)) queue.push_back(nb);
      }
    }
  }
  return inserted;
}

}  // namespace cooperage::pave::detail
