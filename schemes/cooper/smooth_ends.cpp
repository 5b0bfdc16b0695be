// Smoothing the subcaps of one barrel end together (Blacker 1996, sec. 6.1:
// "a smooth of the independent subcaps forming an exterior face of the
// volume is performed to optimize element quality. Since this smooth does
// not affect the topology of the mesh, the structure of the ribs and barrel
// caps remains unaffected"). Done where subcaps meshed independently meet
// across imprinted boundaries: both ends of a barrel with subcaps on both
// ends. Only nodes this sweep made move, over their cap (or, virtual, in
// place); the smooth is kept only when no corner gets worse.
#include "schemes/cooper/smooth_cap.h"
#include "schemes/cooper/sweep_state.h"

#include <algorithm>

namespace cooperage::cooper::detail {

// cite: Blacker 1996, sec. 6.1.
void smooth_ends(SweepState& s) {
  for (size_t b = 0; b < s.barrels.size(); ++b) {
    const BarrelState& st = s.barrels[b];
    std::vector<const Piece*> ends[2];
    for (const Piece& p : s.pieces) {
      if (!p.alive) continue;
      if (p.upper_of == static_cast<int>(b)) ends[0].push_back(&p);
      if (p.lower_of == static_cast<int>(b)) ends[1].push_back(&p);
    }
    if (ends[0].size() < 2 || ends[1].size() < 2) continue;
    for (int e = 0; e < 2; ++e) {
      std::map<int, int> index;
      std::vector<mesh::Vec3> points;
      std::vector<char> movable;
      std::map<int, int> cap_of;  // node -> the real cap it lies on (0: virtual)
      auto local = [&](int n, int cap) {
        auto [it, added] = index.emplace(n, static_cast<int>(points.size()));
        if (added) {
          points.push_back(s.pos(n));
          movable.push_back(s.out.global[static_cast<size_t>(n)] < 0 ? 1 : 0);
          cap_of[n] = cap;
        }
        return it->second;
      };
      std::vector<mesh::Quad> quads;
      std::vector<mesh::Tri> tris;
      // Counter-clockwise about the sweep direction in the barrel's chart.
      auto ccw = [&](auto f) {
        double a = 0;
        for (size_t k = 0; k < f.size(); ++k) {
          const Vec3& p = s.pos(f[k]);
          const Vec3& q = s.pos(f[(k + 1) % f.size()]);
          a += p.dot(st.u) * q.dot(st.v) - p.dot(st.v) * q.dot(st.u);
        }
        if (a < 0) std::reverse(f.begin() + 1, f.end());
        return f;
      };
      for (const Piece* p : ends[e]) {
        for (auto q : p->quads) {
          q = ccw(q);
          quads.push_back(
              {local(q[0], p->cap), local(q[1], p->cap), local(q[2], p->cap), local(q[3], p->cap)});
        }
        for (auto t : p->tris) {
          t = ccw(t);
          tris.push_back({local(t[0], p->cap), local(t[1], p->cap), local(t[2], p->cap)});
        }
      }
      // A node on a real cap is projected back onto it; a virtual one stays
      // in the plane of its end.
      std::vector<int> node_of(points.size());
      for (const auto& [n, i] : index) node_of[static_cast<size_t>(i)] = n;
      auto project = [&](const mesh::Vec3& x) { return x; };
      if (!smooth_cap(points, quads, tris, movable, st.d, project)) continue;
      for (size_t i = 0; i < points.size(); ++i) {
        if (!movable[i]) continue;
        const int n = node_of[i];
        const int cap = cap_of.at(n);
        Vec3 x = points[i];
        if (cap) x = s.model.surface(cap).geometry->project(x).point;
        s.out.coords[static_cast<size_t>(n)] = x;
      }
    }
  }
}

}  // namespace cooperage::cooper::detail
