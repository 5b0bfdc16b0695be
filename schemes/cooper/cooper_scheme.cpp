#include "schemes/cooper/cooper_scheme.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "framework/mesh/loop_nodes.h"
#include "schemes/cooper/column_spacing.h"
#include "schemes/cooper/level_spacing.h"
#include "schemes/cooper/ring_spacing.h"
#include "schemes/cooper/sweep_volume.h"
#include "schemes/cooper/tangent_grading.h"

namespace cooperage::cooper {

Elements elements_of(const scheme::Settings& settings, int volume_id) {
  switch (settings.elements(volume_id)) {
    case io::ElementKind::Wedge: return Elements::Wedge;
    case io::ElementKind::Mixed: return Elements::Mixed;
    case io::ElementKind::Hex: break;
  }
  return Elements::Hex;
}

SweepHints hints_of(const scheme::Settings& settings, int volume_id) {
  const io::VolumeSetting* v = settings.volume(volume_id);
  if (!v || (v->sources.empty() && v->targets.empty() && !v->direction)) return {};
  const std::string where =
      v->where.file.empty() ? std::string() : v->where.file + ":" + std::to_string(v->where.line);
  return {v->sources, v->targets, v->direction, where};
}

const scheme::PolygonMesher* CooperScheme::polygon_mesher(Elements elements) const {
  switch (elements) {
    case Elements::Wedge: return options_.triangle_mesher.get();
    case Elements::Mixed: return options_.quad_dominant_mesher.get();
    case Elements::Hex: break;
  }
  return options_.polygon_mesher.get();
}

std::shared_ptr<const CooperPlan> CooperScheme::plan(const scheme::VolumeView& view) const {
  if (const auto* carried = scheme::carried_plan<CooperPlan>(view);
      carried && carried->plan.volume == view.volume_id) {
    return {std::shared_ptr<const CooperPlan>(), carried};  // not owned: the caller keeps it
  }
  const scheme::Settings& settings = view.settings();
  PlanInputs in;
  in.hints = hints_of(settings, view.volume_id);
  in.elements = elements_of(settings, view.volume_id);
  in.polygon_mesher = polygon_mesher(in.elements) != nullptr;
  in.settings = &settings;
  if (view.neighbours) in.neighbours = *view.neighbours;
  auto p = std::make_shared<CooperPlan>();
  p->plan = plan_volume(view.model, view.volume_id, *registry_, in);
  return p;
}

scheme::Applicability CooperScheme::applicable(const scheme::VolumeView& view) const {
  std::shared_ptr<const CooperPlan> p = plan(view);
  const VolumePlan& plan = p->plan;
  return plan.ok ? scheme::Applicability::yes(plan.score, plan.why, std::move(p))
                 : scheme::Applicability::no(plan.why, std::move(p));
}

namespace {

// A sliver cap the sweep meshes itself: a face of one loop of fewer than 4
// curves, thinner (twice its area over its perimeter) than 5 % of its
// perimeter -- a lens between an arc and a chord under a boss overhanging
// its block by 0.35. With 4 nodes it is one flat quad, with 2 none; it needs
// 6 (two quads). Half-disks (12 % of their perimeter) mesh as one quad and
// keep their intervals.
void fewest_sliver_cap_intervals(const geom::Model& model, const VolumePlan& plan,
                                 intervals::IntervalProblem& problem) {
  if (plan.elements == Elements::Wedge) return;
  for (int cap : plan.roles.by_volume) {
    const geom::Surface& s = model.surface(cap);
    if (s.loops.size() != 1 || s.loops.front().uses.size() >= 4) continue;
    std::vector<int> ids;
    double perimeter = 0;
    for (const auto& use : s.loops.front().uses) {
      ids.push_back(use.curve);
      perimeter += model.curve(use.curve).length;
    }
    if (ids.empty() || 2.0 * s.area >= 0.05 * perimeter * perimeter) continue;
    problem.add_at_least(ids, 6,
                         "surface " + std::to_string(cap) +
                             " (a sliver cap cooper meshes): curves " +
                             mesh::loop_curve_list(s.loops.front()) + " >= 6");
  }
}

}  // namespace

void CooperScheme::constrain(const scheme::VolumeView& view,
                             intervals::IntervalProblem& problem) const {
  const auto p = plan(view);
  if (!p->plan.ok) return;
  add_rows(p->plan.rows, problem);
  fewest_sliver_cap_intervals(view.model, p->plan, problem);
  space_alike_rings(p->plan.along_pairs, problem);
  grade_tangent_ribs(p->plan.facts, p->plan.lattice, problem);
}

scheme::SurfaceRoles CooperScheme::roles(const scheme::VolumeView& view) const {
  const auto held = plan(view);
  const VolumePlan& p = held->plan;
  scheme::SurfaceRoles roles;
  if (!p.ok) return roles;
  for (int s : p.lattice.sides) roles[s] = "submap";
  for (const auto& [cap, upper] : p.order.upper) {
    const auto it = p.roles.scheme.find(cap);
    roles[cap] = it != p.roles.scheme.end() ? it->second : scheme::kMeshedByVolume;
  }
  return roles;
}

// cite: Blacker 1996, sec. 3 (the sides jointly submappable).
std::vector<io::VertexTypeSetting> CooperScheme::vertex_types(
    const scheme::VolumeView& view) const {
  const auto held = plan(view);
  std::vector<io::VertexTypeSetting> out;
  if (!held->plan.ok) return out;
  for (const RetypedCorner& c : held->plan.lattice.retyped) {
    io::VertexTypeSetting t;
    t.surface = c.surface;
    t.vertex = c.vertex;
    t.type = c.turn > 0 ? io::VertexType::End
                        : c.turn == 0 ? io::VertexType::Side : io::VertexType::Corner;
    t.where.file = "volume " + std::to_string(held->plan.volume) + " (cooper)";
    out.push_back(t);
  }
  return out;
}

// cite: Blacker 1996, sec. 6.1 (a stack is meshed from "an existing
// mesh"): a cap meshed beforehand is swept as it is, whoever meshed it.
std::vector<int> CooperScheme::takes_existing_mesh(const scheme::VolumeView& view) const {
  const auto held = plan(view);
  std::vector<int> out;
  if (!held->plan.ok) return out;
  for (const auto& [cap, scheme] : held->plan.roles.scheme) out.push_back(cap);
  return out;
}

// A one-barrel sweep from one cap to one cap (a ring's piece): its upper cap.
int CooperScheme::sweep_source(const scheme::VolumeView& view) const {
  const auto held = plan(view);
  return held->plan.ok ? one_to_one_caps(held->plan.tree).first : 0;
}

// cite: Blacker 1996, sec. 4 (a barrel's rings of ribs on its caps'
// levels). Several barrels only: a one-barrel sweep has no level between
// its ends, and its curves keep their grading.
void CooperScheme::space_curves(const scheme::VolumeView& view, const std::map<int, int>& counts,
                                std::map<int, mesh::SizeFunction>& sizes) const {
  const auto held = plan(view);
  const VolumePlan& p = held->plan;
  if (!p.ok || p.one_barrel() || !p.down) return;
  for (auto& [curve, f] : level_spacing(p.facts, p.lattice, p.order, *p.down, counts))
    sizes[curve] = std::move(f);
  for (auto& [curve, f] : column_spacing(p.facts, p.lattice, *p.down, counts, &sizes))
    sizes[curve] = std::move(f);
}

// cite: Blacker 1996, sec. 4-6 (barrels, subcaps, cap stacks, projection,
// elements); the one-barrel sweep is the same path with one barrel.
scheme::EntityMesh CooperScheme::mesh(const scheme::VolumeView& view,
                                      const scheme::Settings& settings) const {
  scheme::VolumeView own = view;
  if (!own.job) own.job = &settings;
  const auto held = plan(own);
  const VolumePlan& p = held->plan;
  if (!p.ok) {
    throw MeshingError(ErrorCode::NotApplicable, EntityRef::volume(view.volume_id), p.why);
  }
  return sweep_volume(own, p, polygon_mesher(p.elements));
}

std::unique_ptr<scheme::VolumeScheme> make_cooper(const scheme::Registry& registry,
                                                  CooperOptions options) {
  return std::make_unique<CooperScheme>(registry, std::move(options));
}

}  // namespace cooperage::cooper
