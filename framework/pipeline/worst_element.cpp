#include "framework/pipeline/worst_element.h"

#include "framework/quality/hex_metrics.h"
#include "framework/quality/wedge_metrics.h"
#include "framework/scheme/vertex_angles.h"

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

std::string point_text(const geom::Vec3& x) {
  return "(" + number(x.x()) + ", " + number(x.y()) + ", " + number(x.z()) + ")";
}

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

}  // namespace

std::string worst_element_note(const geom::Model& model, const mesh::MeshDB& db, int volume,
                               double bar) {
  const mesh::VolumeMeshData& v = db.volume(volume);
  double worst = bar;
  std::vector<int> nodes;
  const char* kind = "hex";
  for (const mesh::Hex& h : v.hexes) {
    quality::HexNodes p;
    for (int k = 0; k < 8; ++k) p[static_cast<size_t>(k)] = db.node(h[static_cast<size_t>(k)]);
    const double q = quality::hex_scaled_jacobian(p);
    if (q < worst) {
      worst = q;
      nodes.assign(h.begin(), h.end());
      kind = "hex";
    }
  }
  for (const mesh::Wedge& w : v.wedges) {
    quality::WedgeNodes p;
    for (int k = 0; k < 6; ++k) p[static_cast<size_t>(k)] = db.node(w[static_cast<size_t>(k)]);
    const double q = quality::wedge_scaled_jacobian(p);
    if (q < worst) {
      worst = q;
      nodes.assign(w.begin(), w.end());
      kind = "wedge";
    }
  }
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
  std::string near;
  if (!vertices.empty())
    near = "vertex " + std::to_string(*vertices.begin());
  else if (!curves.empty())
    near = "curve " + std::to_string(*curves.begin());
  if (!near.empty()) out += ", next to " + near;
  return out + "; no corner of the part there bounds it: a smaller size on volume " +
         std::to_string(volume) + " or a cut through that spot may raise it";
}

}  // namespace cooperage::pipeline
