#include "framework/pipeline/worst_element.h"

#include "framework/core/text.h"
#include "framework/quality/hex_metrics.h"
#include "framework/quality/wedge_metrics.h"
#include "framework/scheme/vertex_angles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

namespace cooperage::pipeline {
namespace {

std::string number(double v, const char* format = "%.3g") {
  char buf[32];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string point_text(const geom::Vec3& x) { return cooperage::point_text(x.x(), x.y(), x.z()); }

// The sharpest corner at model vertex `vertex` among the faces of `volume`.
struct Corner {
  int surface = 0;
  double degrees = 360.0;
};

Corner sharpest_at(const geom::Model& model, int volume, int vertex) {
  Corner best;
  for (int s : model.surfaces_of(volume)) {
    const geom::Surface& surface = model.surface(s);
    for (size_t l = 0; l < surface.loops.size(); ++l) {
      for (const scheme::LoopCorner& c : scheme::loop_corners(model, s, static_cast<int>(l))) {
        if (c.vertex == vertex && c.angle < best.degrees) best = {s, c.angle};
      }
    }
  }
  return best;
}

// The sharpest convex edge of `volume` that an edge of the element runs
// along: a curve both of whose nodes lie on it (or at its vertices), between
// two faces of the volume; the interior angle from their outward normals
// at the edge's middle, when the element's centre lies behind both faces
// (convex: no bound is read from a concave edge).
struct Edge {
  int curve = 0;
  int surfaces[2] = {0, 0};
  double degrees = 360.0;
};

bool on_curve(const geom::Model& model, const mesh::NodeOwner& o, int curve) {
  if (o.dim == 1) return o.id == curve;
  if (o.dim != 0) return false;
  const geom::Curve& c = model.curve(curve);
  return c.start_vertex == o.id || c.end_vertex == o.id;
}

Edge sharpest_edge(const geom::Model& model, const mesh::MeshDB& db, int volume,
                   const std::vector<int>& nodes, const std::vector<std::pair<int, int>>& edges,
                   const geom::Vec3& centre) {
  Edge best;
  const std::vector<int> faces = model.surfaces_of(volume);
  for (const auto& [a, b] : edges) {
    const mesh::NodeOwner& oa = db.owner(nodes[static_cast<size_t>(a)]);
    const mesh::NodeOwner& ob = db.owner(nodes[static_cast<size_t>(b)]);
    std::set<int> curves;
    for (const mesh::NodeOwner* o : {&oa, &ob}) {
      if (o->dim == 1) curves.insert(o->id);
      if (o->dim == 0)
        curves.insert(model.vertex(o->id).curves.begin(), model.vertex(o->id).curves.end());
    }
    for (int c : curves) {
      if (!on_curve(model, oa, c) || !on_curve(model, ob, c)) continue;
      std::vector<int> sides;
      for (int s : model.curve(c).surfaces) {
        if (std::find(faces.begin(), faces.end(), s) != faces.end()) sides.push_back(s);
      }
      if (sides.size() != 2) continue;
      const geom::Vec3 mid =
          0.5 * (db.node(nodes[static_cast<size_t>(a)]) + db.node(nodes[static_cast<size_t>(b)]));
      geom::Vec3 n[2];
      bool behind = true;
      for (int k = 0; k < 2; ++k) {
        const geom::SurfaceProjection p = model.surface(sides[k]).geometry->project(mid);
        const double out = model.sense_in(sides[k], volume) == geom::Sense::Forward ? 1.0 : -1.0;
        n[k] = out * p.normal;
        behind = behind && (centre - p.point).dot(n[k]) < 0;
      }
      if (!behind) continue;
      const double degrees =
          180.0 - std::acos(std::clamp(n[0].dot(n[1]), -1.0, 1.0)) * 180.0 / M_PI;
      if (degrees < best.degrees) best = {c, {sides[0], sides[1]}, degrees};
    }
  }
  return best;
}

// The element with the smallest scaled Jacobian below `value` so far.
struct Worst {
  double value;
  std::vector<int> nodes;
  const char* kind;
};

// Elements within this of the smallest scaled Jacobian are as bad: a sweep
// repeats a cap's worst shape layer after layer, and rounding alone chose
// among them (a moved part's note named another element).
constexpr double kAsBad = 1e-6;

// With `first` false: lowers worst.value to the smallest value below it.
// With `first` true: takes the first element within kAsBad of worst.value
// (once worst.nodes is set, no later one), so that the element named does
// not depend on rounding.
template <class Nodes, class Element, class Metric>
void scan(const std::vector<Element>& elements, const mesh::MeshDB& db, Metric metric,
          const char* kind, bool first, Worst& worst) {
  for (const Element& e : elements) {
    if (first && !worst.nodes.empty()) return;
    Nodes p;
    for (size_t k = 0; k < e.size(); ++k) p[k] = db.node(e[k]);
    const double q = metric(p);
    if (!first && q < worst.value) worst.value = q;
    if (first && q <= worst.value + kAsBad) worst = {q, std::vector<int>(e.begin(), e.end()), kind};
  }
}

}  // namespace

std::string worst_element_note(const geom::Model& model, const mesh::MeshDB& db, int volume,
                               double bar) {
  const mesh::VolumeMeshData& v = db.volume(volume);
  Worst w{bar, {}, "hex"};
  for (const bool first : {false, true}) {
    if (first && !(w.value < bar)) return {};
    scan<quality::HexNodes>(v.hexes, db, quality::hex_scaled_jacobian, "hex", first, w);
    scan<quality::WedgeNodes>(v.wedges, db, quality::wedge_scaled_jacobian, "wedge", first, w);
  }
  const double worst = w.value;
  const std::vector<int>& nodes = w.nodes;
  const char* kind = w.kind;
  if (nodes.empty() || !(worst > 0)) return {};
  geom::Vec3 centre = geom::Vec3::Zero();
  for (int n : nodes) centre += db.node(n) / static_cast<double>(nodes.size());
  std::string out = "its worst " + std::string(kind) + " has a scaled Jacobian of " +
                    number(worst, "%.3f") + ", below " + number(bar, "%.2g") + ", at " +
                    point_text(centre);
  // A face corner at one of its nodes that caps it.
  std::set<int> vertices, curves;
  for (int n : nodes) {
    const mesh::NodeOwner& o = db.owner(n);
    if (o.dim == 0) vertices.insert(o.id);
    if (o.dim == 1) curves.insert(o.id);
  }
  Corner corner;
  int at = 0;
  for (int vertex : vertices) {
    const Corner c = sharpest_at(model, volume, vertex);
    if (c.degrees < corner.degrees) {
      corner = c;
      at = vertex;
    }
  }
  const double cap = std::sin(corner.degrees * M_PI / 180.0);
  if (at > 0 && corner.degrees < 90.0 && cap < worst + 0.05) {
    return out + ", at vertex " + std::to_string(at) + ", where surface " +
           std::to_string(corner.surface) + " has a corner of " + number(corner.degrees, "%.1f") +
           " degrees: no element there can exceed sin of that angle (" + number(cap, "%.3f") +
           "), at any size";
  }
  // An edge of the part the element runs along, as sharp.
  static const std::vector<std::pair<int, int>> kHexEdges = {{0, 1}, {1, 2}, {2, 3}, {3, 0},
                                                             {4, 5}, {5, 6}, {6, 7}, {7, 4},
                                                             {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  static const std::vector<std::pair<int, int>> kWedgeEdges = {
      {0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
  const Edge edge =
      sharpest_edge(model, db, volume, nodes, nodes.size() == 8 ? kHexEdges : kWedgeEdges, centre);
  const double edge_cap = std::sin(edge.degrees * M_PI / 180.0);
  if (edge.curve > 0 && edge.degrees < 90.0 && edge_cap < worst + 0.05) {
    return out + ", along curve " + std::to_string(edge.curve) + ", where surfaces " +
           std::to_string(edge.surfaces[0]) + " and " + std::to_string(edge.surfaces[1]) +
           " meet at " + number(edge.degrees, "%.1f") +
           " degrees: no element along it can exceed sin of that angle (" +
           number(edge_cap, "%.3f") + "), at any size";
  }
  std::string near;
  if (!vertices.empty())
    near = "vertex " + std::to_string(*vertices.begin());
  else if (!curves.empty())
    near = "curve " + std::to_string(*curves.begin());
  if (!near.empty()) out += ", next to " + near;
  return out + "; no corner or edge of the part there bounds it: a smaller size on volume " +
         std::to_string(volume) + " or a cut through that spot may raise it";
}

}  // namespace cooperage::pipeline
