#include "schemes/map/map_sides.h"

#include "framework/scheme/vertex_angles.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cooperage::map {
namespace {

std::string surface_name(int id) { return "surface " + std::to_string(id); }

std::string degrees(double angle) {
  std::ostringstream s;
  s.precision(0);
  s << std::fixed << angle;
  return s.str();
}

}  // namespace

std::string join_ids(const std::vector<int>& ids, const char* separator) {
  std::string out;
  for (size_t i = 0; i < ids.size(); ++i) {
    if (i) out += separator;
    out += std::to_string(ids[i]);
  }
  return out;
}

std::vector<int> side_curves(const std::vector<geom::CurveUse>& side) {
  std::vector<int> ids;
  ids.reserve(side.size());
  for (const auto& use : side) ids.push_back(use.curve);
  return ids;
}

MapSides analyse_map_surface(const geom::Model& model, int surface_id) {
  MapSides out;
  const geom::Surface& surface = model.surface(surface_id);
  const std::string name = surface_name(surface_id);
  if (surface.loops.size() != 1) {
    out.why = name + " has " + std::to_string(surface.loops.size()) + " loops; map needs one";
    return out;
  }
  const auto corners = scheme::loop_corners(model, surface_id, 0);
  std::vector<int> end_vertices;
  for (const auto& c : corners) {
    if (!c.type) {
      out.why = name + ": vertex " + std::to_string(c.vertex) + " at " + degrees(c.angle) +
                " degrees is too sharp to classify (below " + degrees(scheme::kMinEndAngle) +
                "); map needs END and SIDE vertices";
      return out;
    }
    if (*c.type == scheme::VertexType::Corner || *c.type == scheme::VertexType::Reversal) {
      out.why = name + ": vertex " + std::to_string(c.vertex) + " at " + degrees(c.angle) +
                " degrees is a " + scheme::to_string(*c.type) +
                "; map needs only END and SIDE vertices";
      return out;
    }
    if (*c.type == scheme::VertexType::End) end_vertices.push_back(c.vertex);
  }
  if (end_vertices.size() != 4) {
    std::vector<int> shown(
        end_vertices.begin(),
        end_vertices.begin() + static_cast<long>(std::min<size_t>(end_vertices.size(), 6)));
    out.why = name + ": " + std::to_string(end_vertices.size()) + " END vertices";
    if (!shown.empty()) {
      out.why += " (" + join_ids(shown, ", ") + (end_vertices.size() > 6 ? ", ...)" : ")");
    }
    out.why += ", map needs 4";
    return out;
  }

  const auto& uses = surface.loops.front().uses;
  const auto groups = scheme::sides_between_ends(corners, uses.size());
  for (size_t s = 0; s < 4; ++s) {
    for (int k : groups[s]) out.sides[s].push_back(uses[static_cast<size_t>(k)]);
    out.corner_vertices[s] = corners[static_cast<size_t>(groups[s].front())].vertex;
  }

  // Score: the scaled Jacobian the mapped mesh can reach at its worst
  // vertex (a squashed corner scores low, so the selector may prefer pave).
  double worst = 1.0;
  for (const auto& c : corners) {
    worst = std::min(worst, scheme::predicted_corner_quality(c.angle, *c.type));
  }
  out.score = std::clamp(worst, 0.05, 1.0);
  out.ok = true;
  return out;
}

void add_map_constraints(int surface_id, const MapSides& sides,
                         intervals::IntervalProblem& problem) {
  for (size_t s = 0; s < 2; ++s) {
    const std::vector<int> lhs = side_curves(sides.sides[s]);
    const std::vector<int> rhs = side_curves(sides.sides[s + 2]);
    std::vector<int> a = lhs, b = rhs;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a == b) continue;  // e.g. a cylinder's seam against itself: always true
    problem.add_equal(lhs, rhs,
                      "surface " + std::to_string(surface_id) + " (map): curves " + join_ids(lhs) +
                          " = " + join_ids(rhs));
  }
}

}  // namespace cooperage::map
