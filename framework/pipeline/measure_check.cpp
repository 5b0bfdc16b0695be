#include "framework/pipeline/measure_check.h"

#include "framework/geometry/projection_walk.h"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace cooperage::pipeline {
namespace {

using geom::Vec3;

constexpr double kMaxGapRatio = 0.3;  // of a facet's size: an arc of ~120 degrees

double capped(double gap, double size) {
  const double cap = kMaxGapRatio * size;
  return std::clamp(gap, -cap, cap);
}

Vec3 capped_gap(const Vec3& gap, double size) {
  const double cap = kMaxGapRatio * size;
  const double g = gap.norm();
  return g > cap ? Vec3(gap * (cap / g)) : gap;
}

template <std::size_t N>
std::array<Vec3, N> gather(const std::array<int, N>& e, const mesh::MeshDB& db) {
  std::array<Vec3, N> p;
  for (std::size_t i = 0; i < N; ++i) p[i] = db.node(e[i]);
  return p;
}

/// Sum of term(state, 0..count-1) over fixed chunks, each summed in order
/// with its own state from make_state(), the chunk sums then added in
/// order: parallel, and the same bits for any thread count (the chunks do
/// not depend on the scheduling).
template <class MakeState, class Term>
double chunked_sum_with(std::size_t count, MakeState make_state, Term term) {
  constexpr std::size_t kChunk = 8192;
  const std::size_t chunks = (count + kChunk - 1) / kChunk;
  std::vector<double> partial(chunks, 0.0);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
    auto state = make_state();
    double sum = 0;
    const std::size_t end = std::min(count, (c + 1) * kChunk);
    for (std::size_t e = c * kChunk; e < end; ++e) sum += term(state, e);
    partial[c] = sum;
  });
  double total = 0;
  for (double p : partial) total += p;
  return total;
}

template <class Term>
double chunked_sum(std::size_t count, Term term) {
  return chunked_sum_with(
      count, [] { return 0; }, [&](int, std::size_t e) { return term(e); });
}

/// Area of a bilinear quad (2 x 2 Gauss points of |x_u x x_v|).
double quad_area(const std::array<Vec3, 4>& p) {
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  double a = 0;
  for (double u : g)
    for (double v : g) {
      const Vec3 xu = (1 - v) * (p[1] - p[0]) + v * (p[2] - p[3]);
      const Vec3 xv = (1 - u) * (p[3] - p[0]) + u * (p[2] - p[1]);
      a += 0.25 * xu.cross(xv).norm();
    }
  return a;
}

// ---- 3D: a volume against its CAD volume ---------------------------------------

/// Volume between a facet and its surface, positive where the surface lies
/// outside (the facet cuts the volume short).
template <std::size_t N>
double facet_sliver(const std::array<Vec3, N>& p, geom::ProjectionWalk& surface,
                    double outward_sign) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& q : p) c += q;
  c /= static_cast<double>(N);
  double area = 0, size = 0;
  if constexpr (N == 4) {
    area = 0.5 * (p[2] - p[0]).cross(p[3] - p[1]).norm();
    size = std::max((p[2] - p[0]).norm(), (p[3] - p[1]).norm());
  } else {
    area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    size = std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[0] - p[2]).norm()});
  }
  const geom::SurfaceProjection proj = surface.project(c, size);
  if (!proj.point.allFinite() || !proj.normal.allFinite()) return 0;
  const double gap = capped((proj.point - c).dot(outward_sign * proj.normal), size);
  return area * gap * (N == 4 ? 2.0 / 3.0 : 3.0 / 4.0);
}

MeasureCheck check_volume(const geom::Model& model, const mesh::MeshDB& db, int vid) {
  MeasureCheck m;
  m.entity = EntityRef::volume(vid);
  m.cad = model.volume(vid).volume;
  const mesh::VolumeMeshData& v = db.volume(vid);
  m.mesh = chunked_sum(v.hexes.size(),
                       [&](std::size_t e) { return hex_volume(gather(v.hexes[e], db)); }) +
           chunked_sum(v.wedges.size(),
                       [&](std::size_t e) { return wedge_volume(gather(v.wedges[e], db)); });
  for (const auto& shell : model.volume(vid).shells) {
    for (const geom::SurfaceUse& use : shell) {
      const geom::Surface& s = model.surface(use.surface);
      if (!db.surface_meshed(s.id) || s.geometry->type() == geom::SurfaceType::Plane) continue;
      const mesh::SurfaceMeshData& sm = db.surface(s.id);
      const double out = geom::sign(use.sense);
      auto walk = [&] { return geom::ProjectionWalk(*s.geometry); };
      m.faceting += chunked_sum_with(sm.quads.size(), walk, [&](auto& w, std::size_t e) {
        return facet_sliver(gather(sm.quads[e], db), w, out);
      });
      m.faceting += chunked_sum_with(sm.tris.size(), walk, [&](auto& w, std::size_t e) {
        return facet_sliver(gather(sm.tris[e], db), w, out);
      });
    }
  }
  return m;
}

// ---- 2D: a surface against its CAD area ------------------------------------------

struct EdgeGap {
  Vec3 gap = Vec3::Zero();  ///< from the edge midpoint to the surface or curve
};

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

/// The model curve of surface `s` that a boundary edge (a, b) follows, or 0.
int curve_of_edge(const geom::Model& model, const mesh::MeshDB& db, const geom::Surface& s, int a,
                  int b, const Vec3& mid) {
  for (int n : {a, b})
    if (db.owner(n).dim == 1) return db.owner(n).id;
  if (db.owner(a).dim != 0 || db.owner(b).dim != 0) return 0;
  // Both ends on vertices: a curve of the loops between those vertices
  // (the nearest, when two arcs join the same pair).
  const int va = db.owner(a).id, vb = db.owner(b).id;
  int best = 0;
  double best_distance = 0;
  for (const geom::Loop& loop : s.loops)
    for (const geom::CurveUse& u : loop.uses) {
      const geom::Curve& c = model.curve(u.curve);
      const bool joins = (c.start_vertex == va && c.end_vertex == vb) ||
                         (c.start_vertex == vb && c.end_vertex == va);
      if (!joins) continue;
      const double d = (c.geometry->point(c.geometry->closest_parameter(mid)) - mid).norm();
      if (best == 0 || d < best_distance) {
        best = c.id;
        best_distance = d;
      }
    }
  return best;
}

MeasureCheck check_surface(const geom::Model& model, const mesh::MeshDB& db, int sid) {
  MeasureCheck m;
  m.entity = EntityRef::surface(sid);
  const geom::Surface& s = model.surface(sid);
  m.cad = s.area;
  const mesh::SurfaceMeshData& sm = db.surface(sid);
  const bool planar = s.geometry->type() == geom::SurfaceType::Plane;

  // Every edge once: how many facets use it, then its gap.
  std::unordered_map<std::uint64_t, int> uses;
  auto count = [&](const int* n, int k) {
    for (int i = 0; i < k; ++i) ++uses[edge_key(n[i], n[(i + 1) % k])];
  };
  for (const mesh::Quad& q : sm.quads) count(q.data(), 4);
  for (const mesh::Tri& t : sm.tris) count(t.data(), 3);
  std::unordered_map<std::uint64_t, EdgeGap> gaps;
  gaps.reserve(uses.size());
  geom::ProjectionWalk walk(*s.geometry);  // the facets in order, one after another
  auto gap_of = [&](int a, int b) -> const EdgeGap& {
    const std::uint64_t key = edge_key(a, b);
    auto it = gaps.find(key);
    if (it != gaps.end()) return it->second;
    EdgeGap g;
    const Vec3 mid = 0.5 * (db.node(a) + db.node(b));
    const int curve = uses[key] == 1 ? curve_of_edge(model, db, s, a, b, mid) : 0;
    if (curve > 0) {
      const geom::Curve& c = model.curve(curve);
      if (c.geometry->type() != geom::CurveType::Line) {
        const Vec3 q = c.geometry->point(c.geometry->closest_parameter(mid));
        if (q.allFinite()) g.gap = q - mid;
      }
    } else if (!planar) {
      const geom::SurfaceProjection p = walk.project(mid, (db.node(b) - db.node(a)).norm());
      if (p.point.allFinite()) g.gap = p.point - mid;
    }
    return gaps.emplace(key, g).first->second;
  };

  // Whether a node lies on the surface (to 2 % of the facet's size: real
  // CAD edges sit off their faces by the edge tolerance):
  // only facets whose corners do are credited, so a mesh off its surface
  // is never excused as faceting.
  std::unordered_map<int, double> off_surface;
  auto distance_off = [&](int node, double reach) {
    auto it = off_surface.find(node);
    if (it != off_surface.end()) return it->second;
    const Vec3& x = db.node(node);
    const geom::SurfaceProjection q = walk.project(x, reach);
    const double d = q.point.allFinite() ? (q.point - x).norm() : 0.0;
    return off_surface.emplace(node, d).first->second;
  };

  // One facet: its own area, and the area of the facet split in four with
  // the new nodes on the surface (edge midpoints on their curve or surface,
  // a quad's centre on the surface). The area of (bi)linear facets
  // converges as h^2, so the surface's area over the facet is
  // A_h/2 + (A_h/2 - A_h) / 3 (Richardson): the credit is 4/3 of the gain.
  auto facet = [&](const int* n, int k) {
    Vec3 p[4];
    Vec3 centre = Vec3::Zero();
    for (int i = 0; i < k; ++i) {
      p[i] = db.node(n[i]);
      centre += p[i];
    }
    centre /= k;
    const double area = k == 4 ? quad_area({p[0], p[1], p[2], p[3]})
                               : 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    m.mesh += area;
    Vec3 mid[4];
    double size = 0;
    for (int i = 0; i < k; ++i) {
      const Vec3& a = p[i];
      const Vec3& b = p[(i + 1) % k];
      const double length = (b - a).norm();
      size = std::max(size, length);
      mid[i] = 0.5 * (a + b) + capped_gap(gap_of(n[i], n[(i + 1) % k]).gap, length);
    }
    for (int i = 0; i < k; ++i) {
      if (distance_off(n[i], size) > 0.02 * size) return;  // not on its surface: no credit
    }
    double refined = 0;
    if (k == 4) {
      Vec3 c = centre;
      if (!planar) {
        const geom::SurfaceProjection q = walk.project(centre, size);
        if (q.point.allFinite()) c += capped_gap(q.point - centre, size);
      }
      refined = quad_area({p[0], mid[0], c, mid[3]}) + quad_area({mid[0], p[1], mid[1], c}) +
                quad_area({c, mid[1], p[2], mid[2]}) + quad_area({mid[3], c, mid[2], p[3]});
    } else {
      auto tri = [](const Vec3& a, const Vec3& b, const Vec3& c) {
        return 0.5 * (b - a).cross(c - a).norm();
      };
      refined = tri(p[0], mid[0], mid[2]) + tri(mid[0], p[1], mid[1]) + tri(mid[2], mid[1], p[2]) +
                tri(mid[0], mid[1], mid[2]);
    }
    m.faceting += 4.0 / 3.0 * (refined - area);
  };
  for (const mesh::Quad& q : sm.quads) facet(q.data(), 4);
  for (const mesh::Tri& t : sm.tris) facet(t.data(), 3);
  return m;
}

}  // namespace

double MeasureCheck::deviation() const {
  if (!(cad > 0)) return mesh == 0 ? 0.0 : 1.0;
  return std::abs(mesh + faceting - cad) / cad;
}

double hex_volume(const std::array<Vec3, 8>& p) {
  // The integral of det J over the trilinear cube in closed form: three
  // triple products on the long diagonal 0-6, as in LLNL's hydro codes
  // (Grandy 1997; exact for bilinear faces). A third of the work of the
  // 2 x 2 x 2 Gauss rule, which is exact too; checked against it in tests.
  auto triple = [](const Vec3& a, const Vec3& b, const Vec3& c) { return a.dot(b.cross(c)); };
  const Vec3 d20 = p[2] - p[0], d50 = p[5] - p[0], d70 = p[7] - p[0];
  return (triple((p[3] - p[1]) + (p[7] - p[2]), p[6] - p[3], d20) +
          triple((p[4] - p[3]) + (p[5] - p[7]), p[6] - p[4], d70) +
          triple((p[1] - p[4]) + (p[2] - p[5]), p[6] - p[1], d50)) /
         12.0;
}

double wedge_volume(const std::array<Vec3, 6>& p) {
  // det J is linear in the triangle coordinates (the centroid rule is
  // exact) and quadratic in the height (two Gauss points).
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  double v = 0;
  for (double z : g) {
    const Vec3 dr = (1 - z) * (p[1] - p[0]) + z * (p[4] - p[3]);
    const Vec3 ds = (1 - z) * (p[2] - p[0]) + z * (p[5] - p[3]);
    const Vec3 dz = ((p[3] - p[0]) + (p[4] - p[1]) + (p[5] - p[2])) / 3.0;
    v += 0.25 * dr.cross(ds).dot(dz);
  }
  return v;
}

std::vector<MeasureCheck> compare_measures(const geom::Model& model, const mesh::MeshDB& db) {
  std::vector<std::pair<int, int>> entities;  // (dim, id)
  for (const auto& [id, v] : db.volumes())
    if (v.size() > 0) entities.emplace_back(3, id);
  if (entities.empty()) {
    for (const auto& [id, s] : db.surfaces())
      if (s.size() > 0) entities.emplace_back(2, id);
  }
  std::vector<MeasureCheck> out(entities.size());
  tbb::parallel_for(std::size_t{0}, entities.size(), [&](std::size_t i) {
    const auto [dim, id] = entities[i];
    out[i] = dim == 3 ? check_volume(model, db, id) : check_surface(model, db, id);
  });
  return out;
}

}  // namespace cooperage::pipeline
