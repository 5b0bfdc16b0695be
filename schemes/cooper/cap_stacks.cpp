// Cap stacks (Blacker 1996, sec. 6.1): the matched subcaps through all the
// barrels form stacks; each stack is meshed once -- from its cap meshed by
// a surface scheme, or by the polygon mesher at one of its subcaps (a real
// one when it has any) -- and the mesh is projected to every other subcap
// of the stack "using a least square weighted residual method": the
// barrel's least-squares map of its rings, plus the residuals of the
// subcap's own boundary (whose images are known through the ribs)
// interpolated inside, then onto the real cap.
#include "framework/core/text.h"
#include "schemes/cooper/imprint_polygons.h"
#include "schemes/cooper/pinched_loops.h"
#include "schemes/cooper/residual_field.h"
#include "schemes/cooper/smooth_cap.h"
#include "schemes/cooper/sweep_state.h"
#include "schemes/cooper/untangle_cap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <numeric>
#include <set>
#include <unordered_map>

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

// Where a subcap lies, for a person: " within 0.4 of (1.2, 3.4, 5.6)", the
// centre of its boundary nodes and their farthest from it.
std::string place_of(const SweepState& s, const std::vector<int>& nodes) {
  if (nodes.empty()) return "";
  Vec3 centre = Vec3::Zero();
  for (int n : nodes) centre += s.pos(n);
  centre /= static_cast<double>(nodes.size());
  double radius = 0.0;
  for (int n : nodes) radius = std::max(radius, (s.pos(n) - centre).norm());
  char reach[32];
  std::snprintf(reach, sizeof reach, " within %.2g of ", radius);
  return reach + point_text(centre.x(), centre.y(), centre.z());
}

// Meshes a piece with the polygon mesher in its barrel's chart.
void mesh_with_polygon_mesher(SweepState& s, Piece& p) {
  if (!s.mesher)
    fail(s.vid, "a cap stack without a meshed cap needs a polygon mesher, which is not available");
  const auto [b, end] = home(p);
  const BarrelState& st = s.barrels[b];
  std::map<int, Vec2> xy;
  for (const auto& l : p.loops) {
    for (int n : l) xy[n] = s.plane(b, end == 0 ? s.pos(n) : st.to_upper.apply(s.pos(n)));
  }
  // Loops touching at a node (features meeting at a corner) pass it twice.
  const UnpinchedLoops loops = unpinch_loops(oriented_loops(p.loops, xy), xy);
  const std::vector<int>& boundary = loops.nodes;
  const std::string where = "a subcap of " +
                            (p.cap ? "cap " + std::to_string(p.cap) : std::string("a virtual cap")) +
                            " in " + s.barrel_name(b);
  // Interval counts fix the parity of model curves, not of the pieces
  // their images cut a cap into (sec. 5.3; bench/RESULTS.md, session 37).
  if (boundary.size() % 2 != 0 && s.plan.elements == Elements::Hex) {
    throw MeshingError(ErrorCode::MeshingFailed, EntityRef::volume(s.vid),
                       where + " has an odd number of boundary nodes (" +
                           std::to_string(boundary.size()) + ")" + place_of(s, boundary) +
                           " where imprinted features cross, and no all-hex mesh fits it",
                       "elements \"mixed\" (--elements mixed) meshes it with one column of "
                       "wedges; a smaller size or a <webcut> between the features may mesh it "
                       "all-hex");
  }
  scheme::QuadMesh2D m;
  try {
    m = s.mesher->mesh(loops.points);
  } catch (const std::exception& e) {
    fail(s.vid, "meshing " + where + ": " + e.what());
  }
  if (m.boundary_count != static_cast<int>(boundary.size())) {
    fail(s.vid, "the polygon mesher changed the boundary of a subcap in " + s.barrel_name(b));
  }
  // The mesh lies in the chart's plane. Mapped back onto its end alone (the
  // barrel's least-squares map at a lower end), it misses its own boundary
  // where the end is not a plane, or not an affine image of the chart (a
  // lug's conical underside, a bottom under several such rings), and the
  // nodes next to the boundary fold over it: the boundary's residuals are
  // carried inside, as in a projection (sec. 6.1).
  std::vector<Vec3> chart(m.points.size()), mapped(m.points.size());
  for (size_t k = 0; k < m.points.size(); ++k) {
    chart[k] = st.u * m.points[k].x() + st.v * m.points[k].y() + st.level * st.d;
    mapped[k] = end == 1 ? st.to_lower.apply(chart[k]) : chart[k];
  }
  std::vector<Vec3> boundary_at(boundary.size());
  for (size_t k = 0; k < boundary.size(); ++k) boundary_at[k] = s.pos(boundary[k]);
  const std::vector<Vec3> placed = with_boundary_residuals(chart, mapped, boundary_at);
  std::vector<int> node(m.points.size());
  for (size_t k = 0; k < m.points.size(); ++k) {
    if (k < boundary.size()) {
      node[k] = boundary[k];
      continue;
    }
    Vec3 x = placed[k];
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
    p.tris.push_back({node[static_cast<size_t>(t[0])], node[static_cast<size_t>(t[1])],
                      node[static_cast<size_t>(t[2])]});
  }
  if (loops.pinches > 0) {
    // Both passes of a touching node are one node again: no element may hold it twice.
    auto repeats = [](const auto& e) {
      return std::set<int>(e.begin(), e.end()).size() != e.size();
    };
    const bool bad = std::any_of(p.quads.begin(), p.quads.end(), repeats) ||
                     std::any_of(p.tris.begin(), p.tris.end(), repeats);
    if (bad)
      fail(s.vid, "a subcap in " + s.barrel_name(b) +
                      " touches itself at a node, and its mesh joins the two sides there");
  }
  p.meshed = true;
}

// The surface mesh of a cap meshed beforehand.
void take_surface_mesh(SweepState& s, Piece& p) {
  if (!s.db.surface_meshed(p.cap))
    fail(s.vid, "cap surface " + std::to_string(p.cap) + " is not meshed");
  const mesh::SurfaceMeshData& m = s.db.surface(p.cap);
  for (const auto& q : m.quads)
    p.quads.push_back({s.existing(q[0]), s.existing(q[1]), s.existing(q[2]), s.existing(q[3])});
  for (const auto& t : m.tris)
    p.tris.push_back({s.existing(t[0]), s.existing(t[1]), s.existing(t[2])});
  p.meshed = true;
}

// Where the rings change shape a lot (a hole doubling its radius while the
// outer loop stays), the projected subcap can fold next to its boundary:
// then its new nodes are smoothed (sec. 6.1: "a smooth ... to optimize
// element quality"), kept only if its worst corner improves. Returns the
// worst corner sine of the projected subcap as it is left (<= 0: folded).
// The faces are counter-clockwise about the barrel's direction d where
// they come from and about `d_to` on `to`: the direction the barrel's map
// carries d to. A barrel that turns round an axis ends facing the other
// way (a torus half: its map is a half turn), and judged against d its
// exact image looked folded everywhere and was "untangled" out of shape.
double untangle(SweepState& s, size_t b, const std::vector<mesh::Quad>& quads,
                const std::vector<mesh::Tri>& tris, const std::map<int, int>& index,
                const std::map<int, int>& image, const Piece& to, const Vec3& d_to) {
  const BarrelState& st = s.barrels[b];
  std::vector<int> node(index.size());
  for (const auto& [n, i] : index) node[static_cast<size_t>(i)] = n;
  std::vector<Vec3> before(node.size()), after(node.size());
  std::vector<char> movable(node.size(), 0);
  for (size_t i = 0; i < node.size(); ++i) {
    before[i] = s.pos(node[i]);
    const auto it = image.find(node[i]);
    after[i] = it != image.end() ? s.pos(it->second) : Vec3::Zero();
    movable[i] = it != image.end() ? 1 : 0;
  }
  // Faces counter-clockwise about the barrel's direction where they come from.
  std::vector<mesh::Quad> q = quads;
  std::vector<mesh::Tri> t = tris;
  auto orient = [&](auto& f) {
    Vec3 n = Vec3::Zero();
    for (size_t k = 0; k < f.size(); ++k)
      n += before[static_cast<size_t>(f[k])].cross(
          before[static_cast<size_t>(f[(k + 1) % f.size()])]);
    if (n.dot(st.d) < 0) std::reverse(f.begin() + 1, f.end());
  };
  for (auto& f : q) orient(f);
  for (auto& f : t) orient(f);
  // Positions on the target end for every node (the ring's images too).
  std::map<int, int> across;
  for (const auto& [u, l] : st.rib_pairs) {
    across[u] = l;
    across[l] = u;
  }
  for (size_t i = 0; i < node.size(); ++i) {
    if (movable[i]) continue;
    const auto a = across.find(node[i]);
    after[i] = a != across.end() ? s.pos(a->second) : before[i];
  }
  const double q_before =
      std::min(min_quad_corner_quality(before, q, st.d), min_tri_corner_quality(before, t, st.d));
  const double q_after =
      std::min(min_quad_corner_quality(after, q, d_to), min_tri_corner_quality(after, t, d_to));
  // Within rounding of the source's worst corner is as good: an affine
  // projection gives the same corners, a hair worse or better by rounding,
  // and a moved part was untangled where it was not (campaign seed 7 case 50).
  if (q_after >= std::min(0.5, q_before) - 1e-9) return q_after;
  const auto& g = to.cap ? s.model.surface(to.cap).geometry : nullptr;
  auto onto = [&](const Vec3& x) { return g ? g->project(x).point : x; };
  // A fold that guarded smoothing cannot open (each single move makes a
  // corner worse first) is untangled against the source's corners first.
  const bool untangled = q_after <= 0 && untangle_cap(after, before, q, t, movable, d_to, onto);
  if (!smart_smooth_cap(after, q, t, movable, d_to, onto, 60) && !untangled) return q_after;
  for (size_t i = 0; i < node.size(); ++i) {
    if (movable[i]) s.out.coords[static_cast<size_t>(image.at(node[i]))] = after[i];
  }
  return std::min(min_quad_corner_quality(after, q, d_to), min_tri_corner_quality(after, t, d_to));
}

// Projects piece `from` through barrel b onto its match `to` (sec. 6.1);
// returns the worst corner sine of `to`'s mesh (<= 0: folded).
double project(SweepState& s, size_t b, const Piece& from, Piece& to, bool down) {
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
  std::set<int> seen;  // a node where loops touch is on the ring once
  for (const auto& l : from.loops) {
    for (int n : l) {
      const auto it = across.find(n);
      if (it == across.end())
        fail(s.vid, s.barrel_name(b) + ": a subcap boundary node has no rib across the barrel");
      if (!seen.insert(n).second) continue;
      ring.push_back(n);
      residual.push_back(s.pos(it->second) - map.apply(s.pos(n)));
    }
  }
  // Cap-local numbering: the boundary (ring) first, then the interior.
  std::map<int, int> index;
  std::vector<Vec3> points;
  for (int n : ring) {
    if (index.emplace(n, static_cast<int>(points.size())).second) points.push_back(s.pos(n));
  }
  const size_t boundary = points.size();
  if (boundary != ring.size()) fail(s.vid, s.barrel_name(b) + ": a subcap's loops repeat a node");
  std::vector<mesh::Quad> quads;
  std::vector<mesh::Tri> tris;
  auto local = [&](int n) {
    auto [it, added] = index.emplace(n, static_cast<int>(points.size()));
    if (added) points.push_back(s.pos(n));
    return it->second;
  };
  for (const auto& q : from.quads)
    quads.push_back({local(q[0]), local(q[1]), local(q[2]), local(q[3])});
  for (const auto& t : from.tris) tris.push_back({local(t[0]), local(t[1]), local(t[2])});
  // An affine motion leaves no residual: then the O(interior x boundary)
  // interpolation is skipped (a 4 x 40,000 cap took a minute).
  double largest = 0.0;
  for (const Vec3& x : residual) largest = std::max(largest, x.norm());
  std::vector<Vec3> r;
  if (largest > residual_tolerance(points.data(), boundary)) {
    ResidualField(points, boundary).apply(residual, r);
  } else {
    r.assign(points.size(), Vec3::Zero());
  }
  // The nodes made on `to`, numbered in first use by the faces (as they
  // are added below), then placed in parallel: the map, the residual and
  // the projection onto the cap are independent per node (the projection
  // was most of a 1 M-hex plate's serial cap stack, issue 20).
  std::map<int, int> image;
  std::vector<int> fresh;  // from's nodes, in the order their images are added
  auto first_use = [&](int n) {
    if (across.count(n) == 0 && image.emplace(n, -1).second) fresh.push_back(n);
  };
  for (const auto& q : from.quads)
    for (int n : q) first_use(n);
  for (const auto& t : from.tris)
    for (int n : t) first_use(n);
  const geom::Surface* cap = to.cap ? &s.model.surface(to.cap) : nullptr;
  std::vector<Vec3> placed(fresh.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, fresh.size(), 512),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t k = range.begin(); k != range.end(); ++k) {
                        const int n = fresh[k];
                        const Vec3 y = map.apply(s.pos(n)) + r[static_cast<size_t>(index.at(n))];
                        placed[k] = cap ? cap->geometry->project(y).point : y;
                      }
                    });
  for (size_t k = 0; k < fresh.size(); ++k) {
    image[fresh[k]] = cap ? s.out.add_owned(placed[k], {2, to.cap}) : s.out.add(placed[k]);
  }
  auto image_of = [&](int n) {
    const auto a = across.find(n);
    return a != across.end() ? a->second : image.at(n);
  };
  for (const auto& q : from.quads)
    to.quads.push_back({image_of(q[0]), image_of(q[1]), image_of(q[2]), image_of(q[3])});
  for (const auto& t : from.tris)
    to.tris.push_back({image_of(t[0]), image_of(t[1]), image_of(t[2])});
  to.meshed = true;
  // A face's normal goes with the cofactor of the map's matrix.
  Vec3 d_to = st.d;
  if (const double det = map.A.determinant(); det > 0) {
    const Vec3 n = det * map.A.inverse().transpose() * st.d;
    if (n.allFinite() && n.norm() > 0) d_to = n.normalized();
  }
  return untangle(s, b, quads, tris, index, image, to, d_to);
}

// The faces of `to`, meshed beforehand, in the order and corner order of
// the faces of `from` (as project() makes them): walked face by face from
// the ribs, whose ends pair the two boundaries. A mesh that is not the
// image of `from`'s (another topology, or boundaries paired with a twist)
// is refused, naming both caps.
void match_existing(SweepState& s, size_t b, const Piece& from, Piece& to, bool down) {
  const BarrelState& st = s.barrels[b];
  std::unordered_map<int, int> image;  // from's node -> to's node
  for (const auto& [u, l] : st.rib_pairs) image[down ? u : l] = down ? l : u;
  Piece found;
  found.cap = to.cap;
  take_surface_mesh(s, found);
  const std::string what = "cap " + std::to_string(to.cap) + ", meshed beforehand, is not the " +
                           "image of cap " + std::to_string(from.cap) + "'s mesh across " +
                           s.barrel_name(b);
  if (found.quads.size() != from.quads.size() || found.tris.size() != from.tris.size())
    fail(s.vid, what + " (" + std::to_string(found.quads.size() + found.tris.size()) +
                    " faces, not " + std::to_string(from.quads.size() + from.tris.size()) + ")");
  // Faces of either mesh by their (unordered) edges.
  using Face = std::vector<int>;
  std::vector<Face> src, dst;
  for (const auto& q : from.quads) src.push_back(Face(q.begin(), q.end()));
  for (const auto& t : from.tris) src.push_back(Face(t.begin(), t.end()));
  for (const auto& q : found.quads) dst.push_back(Face(q.begin(), q.end()));
  for (const auto& t : found.tris) dst.push_back(Face(t.begin(), t.end()));
  auto key = [](int a, int c) { return std::make_pair(std::min(a, c), std::max(a, c)); };
  std::map<std::pair<int, int>, std::vector<size_t>> src_edges, dst_edges;
  for (size_t f = 0; f < src.size(); ++f)
    for (size_t k = 0; k < src[f].size(); ++k)
      src_edges[key(src[f][k], src[f][(k + 1) % src[f].size()])].push_back(f);
  for (size_t f = 0; f < dst.size(); ++f)
    for (size_t k = 0; k < dst[f].size(); ++k)
      dst_edges[key(dst[f][k], dst[f][(k + 1) % dst[f].size()])].push_back(f);
  std::vector<int> match(src.size(), -1);
  std::vector<char> used(dst.size(), 0);
  int turn = 0;  // +1: to's faces run as from's, -1: reversed (fixed by the first face)
  auto corner = [](const Face& c, size_t j, int dir, size_t i) {
    const long n = static_cast<long>(c.size());
    return c[static_cast<size_t>(((static_cast<long>(j) + dir * static_cast<long>(i)) % n + n) %
                                 n)];
  };
  // Face f of from onto the face of to holding the image of its edge from
  // corner k to k + 1.
  auto place = [&](size_t f, size_t k) {
    const Face& a = src[f];
    const size_t n = a.size();
    const int p = image.at(a[k]), q = image.at(a[(k + 1) % n]);
    const auto it = dst_edges.find(key(p, q));
    if (it == dst_edges.end()) return false;
    for (size_t g : it->second) {
      const Face& c = dst[g];
      if (used[g] || c.size() != n) continue;
      const size_t j = static_cast<size_t>(std::find(c.begin(), c.end(), p) - c.begin());
      const int dir = corner(c, j, 1, 1) == q ? 1 : -1;
      if (turn != 0 && dir != turn) continue;
      bool fits = true;
      for (size_t i = 0; i < n && fits; ++i) {
        const auto m = image.find(a[(k + i) % n]);
        fits = m == image.end() || m->second == corner(c, j, dir, i);
      }
      if (!fits) continue;
      for (size_t i = 0; i < n; ++i) image[a[(k + i) % n]] = corner(c, j, dir, i);
      turn = dir;
      used[g] = 1;
      match[f] = static_cast<int>(g);
      return true;
    }
    return false;
  };
  // The corner of face g where its edge {x, y} starts.
  auto edge_at = [&](size_t g, int x, int y) {
    const Face& a = src[g];
    for (size_t i = 0; i < a.size(); ++i) {
      const int u = a[i], v = a[(i + 1) % a.size()];
      if ((u == x && v == y) || (u == y && v == x)) return i;
    }
    return a.size();
  };
  std::deque<size_t> queue;
  for (size_t f = 0; f < src.size() && queue.empty(); ++f) {
    for (size_t k = 0; k < src[f].size() && queue.empty(); ++k) {
      const int x = src[f][k], y = src[f][(k + 1) % src[f].size()];
      if (image.count(x) && image.count(y) && src_edges[key(x, y)].size() == 1 && place(f, k))
        queue.push_back(f);
    }
  }
  while (!queue.empty()) {
    const size_t f = queue.front();
    queue.pop_front();
    for (size_t k = 0; k < src[f].size(); ++k) {
      const int x = src[f][k], y = src[f][(k + 1) % src[f].size()];
      for (size_t g : src_edges[key(x, y)]) {
        if (match[g] >= 0) continue;
        const size_t at = edge_at(g, x, y);
        if (at == src[g].size() || !place(g, at))
          fail(s.vid, what + " (the meshes part at a face)");
        queue.push_back(g);
      }
    }
  }
  if (std::find(match.begin(), match.end(), -1) != match.end())
    fail(s.vid, what + " (faces of its source are not reached from its boundary)");
  for (const auto& [u, l] : st.rib_pairs) {
    if (image.at(down ? u : l) != (down ? l : u)) fail(s.vid, what + " (its boundary is twisted)");
  }
  std::set<int> hit;
  for (const auto& [n, x] : image) {
    if (!hit.insert(x).second) fail(s.vid, what + " (two of its nodes meet in one)");
  }
  auto image_of = [&](int n) { return image.at(n); };
  for (const auto& q : from.quads)
    to.quads.push_back({image_of(q[0]), image_of(q[1]), image_of(q[2]), image_of(q[3])});
  for (const auto& t : from.tris)
    to.tris.push_back({image_of(t[0]), image_of(t[1]), image_of(t[2])});
  to.meshed = true;
}

// Projects the meshed seed's mesh through its stack, piece by piece (sec.
// 6.1); returns the worst corner sine of the projected pieces (<= 0: one
// is folded).
double spread(SweepState& s, int seed) {
  double worst = 1.0;
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
        if (to.premeshed) {
          match_existing(s, static_cast<size_t>(b), s.pieces[static_cast<size_t>(m)], to, down);
        } else {
          worst = std::min(worst, project(s, static_cast<size_t>(b),
                                          s.pieces[static_cast<size_t>(m)], to, down));
        }
        queue.push_back(other);
      }
    }
  }
  return worst;
}

// Where the stack's pieces differ in shape (an imprinted line close to a
// rim at one end, far from it at the other), the seed's mesh can fold on
// a piece it is projected onto, next to a corner of that piece's boundary
// that no node inside can open, and the sweep then inverts a hex there. The
// stack's other pieces are tried as the seed in turn (ascending), the
// nodes and elements of a try taken back, and the one whose worst
// projected corner is best is kept (the first seed, as before, when it
// leaves no fold). At most this many seeds.
constexpr size_t kMaxSeeds = 6;

void mesh_from_a_seed(SweepState& s, int first, const std::vector<int>& members) {
  std::vector<int> seeds{first};
  for (int m : members) {
    if (m != first && seeds.size() < kMaxSeeds) seeds.push_back(m);
  }
  const size_t nodes = s.out.coords.size(), owners = s.out.owners.size();
  auto take_back = [&] {
    s.out.coords.resize(nodes);
    s.out.global.resize(nodes);
    if (s.out.owners.size() > owners) s.out.owners.resize(owners);
    for (auto it = s.local.begin(); it != s.local.end();) {
      it = it->second >= static_cast<int>(nodes) ? s.local.erase(it) : std::next(it);
    }
    for (int m : members) {
      Piece& p = s.pieces[static_cast<size_t>(m)];
      p.quads.clear();
      p.tris.clear();
      p.meshed = false;
    }
  };
  int best = first;
  double best_worst = -std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < seeds.size(); ++k) {
    try {
      mesh_with_polygon_mesher(s, s.pieces[static_cast<size_t>(seeds[k])]);
      const double worst = spread(s, seeds[k]);
      if ((k == 0 && worst > 0.0) || seeds.size() == 1) return;
      if (worst > best_worst) {
        best_worst = worst;
        best = seeds[k];
      }
    } catch (const MeshingError&) {
      if (k == 0) throw;  // the first seed's error, as without the others
    }
    take_back();
  }
  mesh_with_polygon_mesher(s, s.pieces[static_cast<size_t>(best)]);
  spread(s, best);
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
    // The seed: the cap meshed beforehand, else a real piece, else any. Two
    // meshed beforehand: a one-to-one sweep closing a ring of sweeps
    // (end_on_existing_mesh), seeded at its source.
    int seed = -1;
    std::vector<int> premeshed;
    for (int m : members) {
      if (s.pieces[static_cast<size_t>(m)].premeshed) premeshed.push_back(m);
    }
    if (premeshed.size() == 1) seed = premeshed.front();
    if (premeshed.size() > 1) {
      const Piece& a = s.pieces[static_cast<size_t>(premeshed[0])];
      const Piece& b = s.pieces[static_cast<size_t>(premeshed[1])];
      const bool ring = premeshed.size() == 2 && members.size() == 2 && s.barrels.size() == 1;
      if (!ring) {
        fail(s.vid, "caps " + std::to_string(a.cap) + " and " + std::to_string(b.cap) +
                        " were both meshed by their surface schemes but lie in one cap stack");
      }
      seed = a.upper_of >= 0 ? a.id : b.id;
    }
    if (seed >= 0) {
      take_surface_mesh(s, s.pieces[static_cast<size_t>(seed)]);
      spread(s, seed);
    } else {
      for (int m : members) {
        if (seed < 0 && s.pieces[static_cast<size_t>(m)].cap) seed = m;
      }
      if (seed < 0) seed = members.front();
      mesh_from_a_seed(s, seed, members);
    }
    for (int m : members) {
      if (!s.pieces[static_cast<size_t>(m)].meshed)
        fail(s.vid, "a subcap of a cap stack was not reached by its stack's mesh");
    }
  }
}

}  // namespace cooperage::cooper::detail
