// Cap stacks (Blacker 1996, sec. 6.1): the matched subcaps through all the
// barrels form stacks; each stack is meshed once -- from its cap meshed by
// a surface scheme, or by the polygon mesher at one of its subcaps (a real
// one when it has any) -- and the mesh is projected to every other subcap
// of the stack "using a least square weighted residual method": the
// barrel's least-squares map of its rings, plus the residuals of the
// subcap's own boundary (whose images are known through the ribs)
// interpolated inside, then onto the real cap.
#include "schemes/cooper/imprint_polygons.h"
#include "schemes/cooper/sweep_state.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>

namespace cooperage::cooper::detail {
namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[static_cast<size_t>(x)] != x) {
    parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    x = parent[static_cast<size_t>(x)];
  }
  return x;
}

// The barrel and end holding a piece (its upper end first).
std::pair<size_t, int> home(const Piece& p) {
  return p.upper_of >= 0 ? std::make_pair(static_cast<size_t>(p.upper_of), 0)
                         : std::make_pair(static_cast<size_t>(p.lower_of), 1);
}

// Meshes a piece with the polygon mesher in its barrel's chart.
void mesh_with_polygon_mesher(SweepState& s, Piece& p) {
  if (!s.mesher) fail(s.vid, "a cap stack without a meshed cap needs a polygon mesher, which is not available");
  const auto [b, end] = home(p);
  const BarrelState& st = s.barrels[b];
  std::map<int, Vec2> xy;
  for (const auto& l : p.loops) {
    for (int n : l) xy[n] = s.plane(b, end == 0 ? s.pos(n) : st.to_upper.apply(s.pos(n)));
  }
  std::vector<std::vector<int>> loops = p.loops;
  size_t outer = 0;
  double best = -1;
  for (size_t l = 0; l < loops.size(); ++l) {
    const double a = std::abs(signed_area(loops[l], xy));
    if (a > best) {
      best = a;
      outer = l;
    }
  }
  std::swap(loops[0], loops[outer]);
  std::vector<std::vector<Eigen::Vector2d>> loops2d;
  std::vector<int> boundary;
  for (size_t l = 0; l < loops.size(); ++l) {
    if ((l == 0) != (signed_area(loops[l], xy) > 0)) std::reverse(loops[l].begin(), loops[l].end());
    loops2d.emplace_back();
    for (int n : loops[l]) {
      loops2d.back().push_back(xy.at(n));
      boundary.push_back(n);
    }
  }
  scheme::QuadMesh2D m;
  try {
    m = s.mesher->mesh(loops2d);
  } catch (const std::exception& e) {
    fail(s.vid, "meshing a subcap of " + (p.cap ? "cap " + std::to_string(p.cap) : std::string("a virtual cap")) +
                    " in " + s.barrel_name(b) + ": " + e.what());
  }
  if (m.boundary_count != static_cast<int>(boundary.size())) {
    fail(s.vid, "the polygon mesher changed the boundary of a subcap in " + s.barrel_name(b));
  }
  std::vector<int> node(m.points.size());
  for (size_t k = 0; k < m.points.size(); ++k) {
    if (k < boundary.size()) {
      node[k] = boundary[k];
      continue;
    }
    Vec3 x = st.u * m.points[k].x() + st.v * m.points[k].y() + st.level * st.d;
    if (end == 1) x = st.to_lower.apply(x);
    if (p.cap) {
      x = s.model.surface(p.cap).geometry->project(x).point;
      node[k] = s.out.add_owned(x, {2, p.cap});
    } else {
      node[k] = s.out.add(x);
    }
  }
  for (const auto& q : m.quads) {
    p.quads.push_back({node[static_cast<size_t>(q[0])], node[static_cast<size_t>(q[1])],
                       node[static_cast<size_t>(q[2])], node[static_cast<size_t>(q[3])]});
  }
  for (const auto& t : m.tris) {
    p.tris.push_back({node[static_cast<size_t>(t[0])], node[static_cast<size_t>(t[1])], node[static_cast<size_t>(t[2])]});
  }
  p.meshed = true;
}

// The surface mesh of a cap meshed beforehand.
void take_surface_mesh(SweepState& s, Piece& p) {
  if (!s.db.surface_meshed(p.cap)) fail(s.vid, "cap surface " + std::to_string(p.cap) + " is not meshed");
  const mesh::SurfaceMeshData& m = s.db.surface(p.cap);
  for (const auto& q : m.quads) p.quads.push_back({s.existing(q[0]), s.existing(q[1]), s.existing(q[2]), s.existing(q[3])});
  for (const auto& t : m.tris) p.tris.push_back({s.existing(t[0]), s.existing(t[1]), s.existing(t[2])});
  p.meshed = true;
}

// Projects piece `from` through barrel b onto its match `to` (sec. 6.1).
void project(SweepState& s, size_t b, const Piece& from, Piece& to, bool down) {
  BarrelState& st = s.barrels[b];
  std::map<int, int> across;  // from's node -> to's node, through the ribs
  for (const auto& [u, l] : st.rib_pairs) {
    if (down) {
      across[u] = l;
    } else {
      across[l] = u;
    }
  }
  const AffineMap& map = down ? st.to_lower : st.to_upper;
  std::vector<int> ring;
  std::vector<Vec3> residual;
  for (const auto& l : from.loops) {
    for (int n : l) {
      const auto it = across.find(n);
      if (it == across.end()) fail(s.vid, s.barrel_name(b) + ": a subcap boundary node has no rib across the barrel");
      ring.push_back(n);
      residual.push_back(s.pos(it->second) - map.apply(s.pos(n)));
    }
  }
  std::map<int, int> image;
  auto image_of = [&](int n) {
    const auto a = across.find(n);
    if (a != across.end()) return a->second;
    const auto it = image.find(n);
    if (it != image.end()) return it->second;
    const Vec3& x = s.pos(n);
    Vec3 sum = Vec3::Zero();
    double wsum = 0;
    for (size_t k = 0; k < ring.size(); ++k) {
      const double d2 = (x - s.pos(ring[k])).squaredNorm();
      const double w = 1.0 / (d2 * std::sqrt(d2) + 1e-300);
      sum += w * residual[k];
      wsum += w;
    }
    Vec3 y = map.apply(x) + (wsum > 0 ? Vec3(sum / wsum) : Vec3::Zero());
    int m;
    if (to.cap) {
      y = s.model.surface(to.cap).geometry->project(y).point;
      m = s.out.add_owned(y, {2, to.cap});
    } else {
      m = s.out.add(y);
    }
    image[n] = m;
    return m;
  };
  for (const auto& q : from.quads) to.quads.push_back({image_of(q[0]), image_of(q[1]), image_of(q[2]), image_of(q[3])});
  for (const auto& t : from.tris) to.tris.push_back({image_of(t[0]), image_of(t[1]), image_of(t[2])});
  to.meshed = true;
}

}  // namespace

// cite: Blacker 1996, sec. 6.1 (forming and meshing cap stacks).
void mesh_stacks(SweepState& s) {
  const size_t n = s.pieces.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const BarrelState& st : s.barrels) {
    for (const auto& [u, l] : st.matches) {
      const int a = find_root(parent, u), z = find_root(parent, l);
      if (a != z) parent[static_cast<size_t>(std::max(a, z))] = std::min(a, z);
    }
  }
  std::map<int, std::vector<int>> stacks;
  for (const Piece& p : s.pieces) {
    if (p.alive) stacks[find_root(parent, p.id)].push_back(p.id);
  }
  for (const auto& [root, members] : stacks) {
    // The seed: the cap meshed beforehand, else a real piece, else any.
    int seed = -1;
    for (int m : members) {
      const Piece& p = s.pieces[static_cast<size_t>(m)];
      if (!p.premeshed) continue;
      if (seed >= 0) {
        fail(s.vid, "caps " + std::to_string(s.pieces[static_cast<size_t>(seed)].cap) + " and " + std::to_string(p.cap) +
                        " were both meshed by their surface schemes but lie in one cap stack");
      }
      seed = m;
    }
    if (seed >= 0) {
      take_surface_mesh(s, s.pieces[static_cast<size_t>(seed)]);
    } else {
      for (int m : members) {
        if (seed < 0 && s.pieces[static_cast<size_t>(m)].cap) seed = m;
      }
      if (seed < 0) seed = members.front();
      mesh_with_polygon_mesher(s, s.pieces[static_cast<size_t>(seed)]);
    }
    std::deque<int> queue{seed};
    while (!queue.empty()) {
      const int m = queue.front();
      queue.pop_front();
      const Piece& from = s.pieces[static_cast<size_t>(m)];
      for (const int b : {from.upper_of, from.lower_of}) {
        if (b < 0) continue;
        const bool down = b == from.upper_of;
        const BarrelState& st = s.barrels[static_cast<size_t>(b)];
        for (const auto& [u, l] : st.matches) {
          const int other = down ? (u == m ? l : -1) : (l == m ? u : -1);
          if (other < 0) continue;
          Piece& to = s.pieces[static_cast<size_t>(other)];
          if (to.meshed) continue;
          project(s, static_cast<size_t>(b), s.pieces[static_cast<size_t>(m)], to, down);
          queue.push_back(other);
        }
      }
    }
    for (int m : members) {
      if (!s.pieces[static_cast<size_t>(m)].meshed) fail(s.vid, "a subcap of a cap stack was not reached by its stack's mesh");
    }
  }
}

}  // namespace cooperage::cooper::detail
