// A Cooperage plug-in: the surface scheme "triprimitive", an all-quad mesh
// of a three-sided face. Each side is split at a point M_k, the three points
// are joined to a centre C, and the three four-sided patches (corner,
// M_k, C, M_k-1) are filled by transfinite interpolation. A triangle gets
// quads with one 60-degree corner each where paving has to place irregular
// nodes wherever its fronts meet.
//
// Counts: with n0, n1, n2 intervals on the sides and s_k on the spoke from
// M_k to C, each patch is mapped (opposite sides equal), which gives
// n0 = s1 + s2, n1 = s2 + s0, n2 = s0 + s1: the total is even and every side
// is at most the sum of the other two minus 2 (each spoke >= 1 interval).
//
// Built against an installed Cooperage (find_package(Cooperage)); loaded by
// `cooperage --plugin libcooperage_triprimitive.so`, a journal's
// <plugin file="..."/>, or COOPERAGE_PLUGIN_PATH.
#include <framework/core/error.h>
#include <framework/scheme/plugin.h>
#include <framework/scheme/vertex_angles.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace cooperage;
using geom::Vec3;

// The three sides of a face: the uses of its single loop between its three
// END vertices (angles 45..130 degrees), every other vertex a SIDE one.
struct Sides {
  std::vector<std::vector<int>> uses;  // per side, indices into the loop's uses
  double score = 0.0;                  // the worst corner's predicted quality
  std::string why;                     // empty when it is a three-sided face
};

Sides three_sides(const geom::Model& model, int surface_id) {
  Sides out;
  const std::string name = "surface " + std::to_string(surface_id);
  const geom::Surface& s = model.surface(surface_id);
  if (s.loops.size() != 1) {
    out.why = name + " has " + std::to_string(s.loops.size()) + " loops; triprimitive needs one";
    return out;
  }
  const auto corners = scheme::loop_corners(model, surface_id, 0);
  int ends = 0;
  // Three quads meet at the centre at about 120 degrees.
  out.score = scheme::predicted_corner_quality(120.0, scheme::VertexType::End);
  for (const auto& c : corners) {
    if (!c.type || (*c.type != scheme::VertexType::End && *c.type != scheme::VertexType::Side)) {
      out.why = name + ": vertex " + std::to_string(c.vertex) + " has an interior angle of " +
                std::to_string(static_cast<int>(std::lround(c.angle))) +
                " degrees; triprimitive needs corners of 45 to 130 degrees and flat sides";
      return out;
    }
    ends += *c.type == scheme::VertexType::End ? 1 : 0;
    out.score = std::min(out.score, scheme::predicted_corner_quality(c.angle, *c.type));
  }
  if (ends != 3) {
    out.why = name + " has " + std::to_string(ends) + " corners; triprimitive needs 3";
    return out;
  }
  out.uses = scheme::sides_between_ends(corners, s.loops[0].uses.size());
  return out;
}

// A side's node chain in loop order, junction nodes once.
std::vector<int> side_chain(const mesh::MeshDB& db, int surface_id,
                            const std::vector<geom::CurveUse>& loop, const std::vector<int>& uses) {
  std::vector<int> chain;
  for (int k : uses) {
    const geom::CurveUse& use = loop[static_cast<size_t>(k)];
    if (!db.curve_meshed(use.curve)) {
      throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(surface_id),
                         "curve " + std::to_string(use.curve) + " is not meshed");
    }
    std::vector<int> nodes = db.curve_nodes(use.curve);
    if (use.sense == geom::Sense::Reversed) std::reverse(nodes.begin(), nodes.end());
    chain.insert(chain.end(), nodes.begin() + (chain.empty() ? 0 : 1), nodes.end());
  }
  return chain;
}

// The plan applicable() returns: cooperage keeps it with the selector's
// choice and hands it back in view.plan to constrain() and mesh(), so the
// corners are found once per run and the scheme itself keeps no state.
struct TriPlan final : scheme::PlanData {
  int surface_id = 0;
  Sides sides;
};

// The plan the view carries, else one made now (a caller without a plan).
std::shared_ptr<const TriPlan> plan_of(const scheme::SurfaceView& view) {
  if (const auto* carried = scheme::carried_plan<TriPlan>(view);
      carried && carried->surface_id == view.surface_id) {
    return {std::shared_ptr<const TriPlan>(), carried};  // the caller keeps it
  }
  auto p = std::make_shared<TriPlan>();
  p->surface_id = view.surface_id;
  p->sides = three_sides(view.model, view.surface_id);
  return p;
}

class TriPrimitive final : public scheme::SurfaceScheme {
 public:
  std::string_view name() const override { return "triprimitive"; }

  // Any face it meshes may be a cooper source cap, in hex or mixed mode.
  scheme::Role serves() const override { return scheme::Role::QuadCap | scheme::Role::MixedCap; }

  scheme::Applicability applicable(const scheme::SurfaceView& view) const override {
    std::shared_ptr<const TriPlan> plan = plan_of(view);
    const Sides& sides = plan->sides;
    if (!sides.why.empty()) return scheme::Applicability::no(sides.why);
    return scheme::Applicability::yes(sides.score,
                                      "surface " + std::to_string(view.surface_id) +
                                          ": three corners, three patches meeting at the centre",
                                      std::move(plan));
  }

  void constrain(const scheme::SurfaceView& view,
                 intervals::IntervalProblem& problem) const override {
    const std::shared_ptr<const TriPlan> plan = plan_of(view);
    const Sides& sides = plan->sides;
    if (!sides.why.empty()) return;
    const auto& loop = view.surface().loops[0].uses;
    const std::string tag = "surface " + std::to_string(view.surface_id) + " (triprimitive)";
    std::vector<int> all;
    for (const auto& side : sides.uses) {
      for (int k : side) all.push_back(loop[static_cast<size_t>(k)].curve);
    }
    problem.add_even(all, tag + ": the three sides' sum even");
    // other two - this one >= 2, i.e. the spoke opposite this side >= 1.
    for (size_t k = 0; k < 3; ++k) {
      std::vector<intervals::LinearTerm> terms;
      for (size_t j = 0; j < 3; ++j) {
        for (int u : sides.uses[j])
          terms.push_back({loop[static_cast<size_t>(u)].curve, j == k ? -1 : 1});
      }
      problem.add_linear(terms, intervals::Sense::GreaterEqual, 2,
                         tag + ": side " + std::to_string(k) + " < the other two");
    }
  }

  scheme::EntityMesh mesh(const scheme::SurfaceView& view,
                          const scheme::Settings& /*params*/) const override {
    const int sid = view.surface_id;
    auto fail = [sid](const std::string& message) {
      throw MeshingError(ErrorCode::MeshingFailed, EntityRef::surface(sid), message);
    };
    const std::shared_ptr<const TriPlan> plan = plan_of(view);
    const Sides& sides = plan->sides;
    if (!sides.why.empty()) fail(sides.why);
    if (!view.mesh) fail("triprimitive needs the meshed curves");
    const mesh::MeshDB& db = *view.mesh;
    const auto& loop = view.surface().loops[0].uses;
    std::array<std::vector<int>, 3> chain;
    std::array<int, 3> n{};
    for (size_t k = 0; k < 3; ++k) {
      chain[k] = side_chain(db, sid, loop, sides.uses[k]);
      n[k] = static_cast<int>(chain[k].size()) - 1;
    }
    // Spoke counts: n_k = s_(k+1) + s_(k+2).
    std::array<int, 3> s{};
    for (size_t k = 0; k < 3; ++k) {
      const int twice = n[(k + 1) % 3] + n[(k + 2) % 3] - n[k];
      if (twice < 2 || twice % 2 != 0) {
        fail("side intervals " + std::to_string(n[0]) + ", " + std::to_string(n[1]) + ", " +
             std::to_string(n[2]) +
             " have no triprimitive mesh (even sum, each side below the "
             "other two)");
      }
      s[k] = twice / 2;
    }
    const geom::SurfaceGeometry& geometry = *view.surface().geometry;
    scheme::EntityMesh out;
    std::map<int, int> local_of_global;
    auto boundary = [&](int global) {
      auto [it, added] = local_of_global.emplace(global, 0);
      if (added) it->second = out.add(db.node(global), global);
      return it->second;
    };
    // M_k splits side k after s_(k+2) intervals; C is their mean on the surface.
    std::array<int, 3> split{};
    Vec3 centre = Vec3::Zero();
    for (size_t k = 0; k < 3; ++k) {
      split[k] = s[(k + 2) % 3];
      centre += db.node(chain[k][static_cast<size_t>(split[k])]) / 3.0;
    }
    const int c = out.add(geometry.project(centre).point);
    // spoke[k][j]: local nodes from M_k (j = 0) to C (j = s_k).
    std::array<std::vector<int>, 3> spoke;
    for (size_t k = 0; k < 3; ++k) {
      const int m = boundary(chain[k][static_cast<size_t>(split[k])]);
      spoke[k].push_back(m);
      for (int j = 1; j < s[k]; ++j) {
        const double t = static_cast<double>(j) / s[k];
        spoke[k].push_back(out.add(
            geometry.project((1 - t) * out.coords[static_cast<size_t>(m)] + t * centre).point));
      }
      spoke[k].push_back(c);
    }
    // Patch k: corner P_k, i along side k to M_k, j back along side k-1 to M_(k-1).
    for (size_t k = 0; k < 3; ++k) {
      const size_t prev = (k + 2) % 3;
      const int a = split[k], b = s[k];
      const auto at = [&](int i, int j) -> int {  // boundary of the patch
        if (j == 0) return boundary(chain[k][static_cast<size_t>(i)]);
        if (i == 0) return boundary(chain[prev][static_cast<size_t>(n[prev] - j)]);
        if (i == a) return spoke[k][static_cast<size_t>(j)];
        return spoke[prev][static_cast<size_t>(i)];  // j == b
      };
      const auto x = [&](int i, int j) { return out.coords[static_cast<size_t>(at(i, j))]; };
      std::vector<int> grid(static_cast<size_t>((a + 1) * (b + 1)));
      for (int i = 0; i <= a; ++i) {
        for (int j = 0; j <= b; ++j) {
          int& g = grid[static_cast<size_t>(i * (b + 1) + j)];
          if (i == 0 || j == 0 || i == a || j == b) {
            g = at(i, j);
            continue;
          }
          const double u = static_cast<double>(i) / a, v = static_cast<double>(j) / b;
          const Vec3 p = (1 - v) * x(i, 0) + v * x(i, b) + (1 - u) * x(0, j) + u * x(a, j) -
                         ((1 - u) * (1 - v) * x(0, 0) + u * (1 - v) * x(a, 0) +
                          (1 - u) * v * x(0, b) + u * v * x(a, b));
          g = out.add(geometry.project(p).point);
        }
      }
      for (int i = 0; i < a; ++i) {
        for (int j = 0; j < b; ++j) {
          const auto q = [&](int di, int dj) {
            return grid[static_cast<size_t>((i + di) * (b + 1) + j + dj)];
          };
          out.quads.push_back({q(0, 0), q(1, 0), q(1, 1), q(0, 1)});
        }
      }
    }
    return out;
  }
};

}  // namespace

COOPERAGE_PLUGIN_ABI

extern "C" COOPERAGE_PLUGIN_EXPORT void cooperage_register(cooperage::scheme::Registry& registry) {
  registry.add(std::make_unique<TriPrimitive>());
}
