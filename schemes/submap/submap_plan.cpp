#include "schemes/submap/submap_plan.h"

#include <cmath>
#include <map>

#include "schemes/submap/directions.h"
#include "schemes/submap/uv_chart.h"

namespace cooperage::submap {
namespace {

VertexType from_journal(io::VertexType t) {
  switch (t) {
    case io::VertexType::End: return VertexType::End;
    case io::VertexType::Side: return VertexType::Side;
    case io::VertexType::Corner: return VertexType::Corner;
    case io::VertexType::Reversal: return VertexType::Reversal;
  }
  return VertexType::Side;
}

// Direction of travel of a curve use in the surface's parameters, scaled to
// model lengths: the unwrapped parameter difference from its first to its
// last point (samples keep the unwrapping continuous).
Vec2 use_chord(const geom::Model& model, const geom::CurveUse& use, const UvChart& chart) {
  const geom::Curve& c = model.curve(use.curve);
  const auto [t0, t1] = c.geometry->range();
  constexpr int kSamples = 8;
  Vec2 first = Vec2::Zero(), prev = Vec2::Zero();
  for (int s = 0; s <= kSamples; ++s) {
    double a = static_cast<double>(s) / kSamples;
    if (use.sense == geom::Sense::Reversed) a = 1.0 - a;
    const Vec3 p = c.geometry->point(t0 + a * (t1 - t0));
    prev = s == 0 ? chart.uv(p) : chart.uv_near(p, prev);
    if (s == 0) first = prev;
  }
  return (prev - first).cwiseProduct(chart.metric());
}

std::string degrees(double a) { return std::to_string(static_cast<int>(std::lround(a))); }

}  // namespace

SubmapPlan plan_submap(const geom::Model& model, int surface_id,
                       const std::vector<io::VertexTypeSetting>& pins,
                       const ClassifyOptions& options) {
  SubmapPlan plan;
  const geom::Surface& surface = model.surface(surface_id);
  const std::string prefix = "surface " + std::to_string(surface_id) + ": ";
  if (surface.loops.empty()) {
    plan.why = prefix + "has no boundary loop";
    return plan;
  }
  std::map<int, VertexType> pinned;
  for (const auto& p : pins) {
    if (p.surface == surface_id) pinned[p.vertex] = from_journal(p.type);
  }
  double deviation = 0.0;
  int corner_count = 0, changed = 0;
  double worst_quality = 1.0;  // predicted scaled Jacobian at the worst vertex
  for (size_t l = 0; l < surface.loops.size(); ++l) {
    LoopPlan lp;
    lp.uses = surface.loops[l].uses;
    lp.corners = scheme::loop_corners(model, surface_id, static_cast<int>(l));
    std::vector<CornerInput> inputs;
    for (const auto& c : lp.corners) {
      CornerInput in;
      in.angle = c.angle;
      auto it = pinned.find(c.vertex);
      if (it != pinned.end()) in.pinned = it->second;
      inputs.push_back(in);
    }
    const int target = l == 0 ? 4 : -4;
    lp.types = classify_loop(inputs, target, options);
    if (!lp.types.ok) {
      if (lp.types.bad_corner >= 0) {
        const auto& c = lp.corners[static_cast<size_t>(lp.types.bad_corner)];
        plan.why = prefix + "vertex " + std::to_string(c.vertex) + " " + lp.types.why;
      } else {
        plan.why = prefix + (l == 0 ? std::string() : "hole loop " + std::to_string(l) + ": ") +
                   lp.types.why;
      }
      return plan;
    }
    for (size_t k = 0; k < lp.corners.size(); ++k) {
      // A REVERSAL is a slit in the lattice: both of its sides would fall on
      // the same lattice points, which the lattice fill cannot mesh.
      if (lp.types.types[k] == VertexType::Reversal) {
        plan.why = prefix + "vertex " + std::to_string(lp.corners[k].vertex) + " at " +
                   degrees(lp.corners[k].angle) +
                   " degrees is a REVERSAL; the submap lattice fill cannot mesh the slit it makes";
        return plan;
      }
      deviation += std::abs(lp.corners[k].angle - scheme::ideal_angle_degrees(lp.types.types[k]));
      worst_quality = std::min(
          worst_quality, scheme::predicted_corner_quality(lp.corners[k].angle, lp.types.types[k]));
    }
    corner_count += static_cast<int>(lp.corners.size());
    changed += lp.types.changed;
    lp.directions = use_directions(lp.types.types);
    plan.loops.push_back(std::move(lp));
  }

  // Holes: rotate each hole's directions so that they match the outer
  // loop's i and j, judged by the uses' directions in the surface parameters.
  if (plan.loops.size() > 1) {
    const UvChart chart(*surface.geometry);
    Vec2 ref[2] = {Vec2::Zero(), Vec2::Zero()};
    const LoopPlan& outer = plan.loops.front();
    for (size_t u = 0; u < outer.uses.size(); ++u) {
      const int d = outer.directions[u];
      ref[d % 2] += (d < 2 ? 1.0 : -1.0) * use_chord(model, outer.uses[u], chart);
    }
    for (auto& r : ref) {
      if (r.norm() > 0) r.normalize();
    }
    for (size_t l = 1; l < plan.loops.size(); ++l) {
      LoopPlan& hole = plan.loops[l];
      std::vector<Vec2> chords;
      for (const auto& use : hole.uses) {
        Vec2 c = use_chord(model, use, chart);
        if (c.norm() > 0) c.normalize();
        chords.push_back(c);
      }
      int best_r = 0;
      double best = -1e300;
      for (int r = 0; r < 4; ++r) {
        double score = 0.0;
        for (size_t u = 0; u < hole.uses.size(); ++u) {
          const int d = (hole.directions[u] + r) % 4;
          score += (d < 2 ? 1.0 : -1.0) * chords[u].dot(ref[d % 2]);
        }
        // A quarter turn wins only by more than noise: the scores are
        // intrinsic (angles in the surface), so ties keep the smaller r.
        if (score > best + 1e-9 * static_cast<double>(hole.uses.size())) {
          best = score;
          best_r = r;
        }
      }
      for (int& d : hole.directions) d = (d + best_r) % 4;
    }
  }

  plan.ok = true;
  const double mean_dev = corner_count > 0 ? deviation / corner_count : 0.0;
  // The scaled Jacobian the lattice can reach at its worst vertex: on the
  // same scale as map and pave, so the selector compares like with like
  // (ties go to map, registered first).
  plan.score = std::max(0.05, worst_quality);
  std::map<VertexType, int> count;
  for (const auto& lp : plan.loops) {
    for (VertexType t : lp.types.types) ++count[t];
  }
  std::string summary;
  for (VertexType t :
       {VertexType::End, VertexType::Side, VertexType::Corner, VertexType::Reversal}) {
    if (count[t] == 0) continue;
    if (!summary.empty()) summary += ", ";
    summary += std::to_string(count[t]) + " " + scheme::to_string(t);
  }
  plan.why =
      prefix + summary + " vertices in " + std::to_string(plan.loops.size()) +
      (plan.loops.size() == 1 ? " loop" : " loops") +
      (changed > 0 ? " (" + std::to_string(changed) + " reclassified to meet the sum rule)" : "") +
      ", mean angle deviation " + degrees(mean_dev) + " degrees";
  return plan;
}

void add_submap_constraints(int surface_id, const SubmapPlan& plan,
                            intervals::IntervalProblem& problem) {
  if (!plan.ok) return;
  const std::string prefix = "surface " + std::to_string(surface_id) + " (submap) ";
  std::vector<std::vector<DirectedUse>> directed;
  for (const auto& lp : plan.loops) {
    std::vector<DirectedUse> uses;
    for (size_t u = 0; u < lp.uses.size(); ++u)
      uses.push_back({lp.uses[u].curve, lp.directions[u]});
    directed.push_back(std::move(uses));
  }
  for (size_t l = 0; l < directed.size(); ++l) {
    const auto axes = loop_balance(directed[l]);
    for (size_t a = 0; a < 2; ++a) {
      if (axes[a].empty()) continue;
      std::vector<intervals::LinearTerm> terms;
      for (const auto& [curve, coeff] : axes[a]) terms.push_back({curve, coeff});
      problem.add_linear(
          std::move(terms), intervals::Sense::Equal, 0,
          prefix + "loop " + std::to_string(l) + ": " + (a == 0 ? "+i = -i" : "+j = -j"));
    }
  }
  for (size_t l = 1; l < directed.size(); ++l) {
    for (int d : {kPlusI, kPlusJ}) {
      std::map<int, int> coeff;
      for (const auto& [curve, k] : along(directed[0], d)) coeff[curve] += k;
      for (const auto& [curve, k] : along(directed[l], d)) coeff[curve] -= k;
      std::vector<intervals::LinearTerm> terms;
      for (const auto& [curve, k] : coeff) {
        if (k != 0) terms.push_back({curve, k});
      }
      if (terms.empty()) continue;
      problem.add_linear(
          std::move(terms), intervals::Sense::GreaterEqual, 2,
          prefix + "hole loop " + std::to_string(l) + " fits along " + direction_name(d));
    }
  }
}

}  // namespace cooperage::submap
