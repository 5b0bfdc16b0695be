#include "plan_command.h"

#include "json_writer.h"

#include "framework/core/text.h"
#include "framework/decompose/report_text.h"
#include "framework/pipeline/check_settings.h"
#include "framework/pipeline/mesh_size.h"
#include "framework/pipeline/model_job.h"
#include "schemes/builtin_schemes.h"
#include "schemes/cooper/cooper_scheme.h"
#include "selector/select_schemes.h"

#include <iostream>
#include <limits>
#include <sstream>

namespace cooperage::app {
namespace {

constexpr int kExitRefused = 2;          // as `mesh` and `run` exit for a volume no scheme fits
constexpr size_t kMaxRefusalLine = 300;  // the whole reason is in the plan above

// The cooper plan of a volume the selection gave to cooper (Blacker 1996,
// sec. 4: its barrel tree), or null.
// The selector keeps the plan cooper's applicable() returned (no second
// analysis).
const cooper::VolumePlan* cooper_plan(const selector::Choice& c) {
  if (c.dim != 3 || c.scheme != "cooper") return nullptr;
  for (const selector::Candidate& k : c.candidates) {
    if (k.scheme != c.scheme) continue;
    const auto* p = dynamic_cast<const cooper::CooperPlan*>(k.applicability.plan.get());
    return p ? &p->plan : nullptr;
  }
  return nullptr;
}

// Every volume scheme's verdict on a volume the selection refused.
std::vector<selector::Candidate> refused_candidates(int volume, const geom::Model& model,
                                                    const scheme::Registry& registry,
                                                    const scheme::Settings& job) {
  std::vector<selector::Candidate> out;
  for (const scheme::VolumeScheme* s : registry.volume_schemes()) {
    out.push_back(selector::Candidate{
        std::string(s->name()), s->applicable(scheme::VolumeView{model, volume, nullptr, &job})});
  }
  return out;
}

void write_text(const selector::Selection& sel, const decompose::Report& cuts,
                const std::string& decomposition_failed, bool intervals_checked,
                const geom::Model& model, const scheme::Registry& registry,
                const scheme::Settings& job, std::ostream& out) {
  auto entity = [&](const selector::Choice& c) {
    out << (c.dim == 3 ? "volume " : "surface ") << c.id << ": "
        << (c.scheme == scheme::kMeshedByVolume ? std::string("meshed by its volume") : c.scheme)
        << "  -- " << c.reason << "\n";
    for (const auto& k : c.candidates) out << "    " << selector::describe(k) << "\n";
    if (const auto w = sel.waits_for.find(c.id); c.dim == 3 && w != sel.waits_for.end()) {
      out << "    meshed after volume";
      for (int v : w->second) out << " " << v;
      out << " (takes its mesh of a shared surface)\n";
    }
    if (const auto p = cooper_plan(c); p && p->ok) {
      std::istringstream lines(cooper::describe_plan(*p));
      for (std::string line; std::getline(lines, line);) out << "    " << line << "\n";
    }
  };
  const std::vector<std::string> cut_lines = decompose::report_lines(cuts);
  if (!cut_lines.empty()) {
    out << "decomposition (" << cuts.tried << (cuts.tried == 1 ? " cut" : " cuts") << " tried)\n";
    for (const auto& line : cut_lines) out << "  " << line << "\n";
  }
  if (!decomposition_failed.empty())
    out << "decomposition failed: " << decomposition_failed << "\n";
  if (!sel.volumes.empty() || !sel.refused.empty()) out << "volumes\n";
  auto refused = sel.refused.begin();
  auto print_refused_before = [&](int id) {  // refusals in id order among the choices
    for (; refused != sel.refused.end() && refused->first < id; ++refused) {
      out << "volume " << refused->first << ": refused  -- " << refused->second.message << "\n";
      for (const auto& k : refused_candidates(refused->first, model, registry, job)) {
        out << "    " << selector::describe(k) << "\n";
      }
    }
  };
  for (const auto& c : sel.volumes) {
    print_refused_before(c.id);
    entity(c);
  }
  print_refused_before(std::numeric_limits<int>::max());
  out << "surfaces\n";
  for (const auto& c : sel.surfaces) entity(c);
  for (const auto& r : sel.relaxations) out << "relaxed " << r << "\n";
  if (!intervals_checked) out << "interval feasibility not checked: no element size given\n";
}

// The barrel tree as JSON: direction, barrels (1-based), their sides, the
// imprint operation and both ends (real caps with who meshes them, virtual
// caps with the barrel on their other side).
void write_barrel_tree(JsonWriter& j, const cooper::VolumePlan& p) {
  j.begin_object();
  j.key("candidate");
  j.value(p.candidate);
  j.key("direction");
  if (p.down) {
    j.value(std::vector<double>{p.down->x(), p.down->y(), p.down->z()});
  } else {
    j.value(std::vector<double>{});
  }
  j.key("barrels");
  j.begin_array();
  for (const cooper::BarrelNode& b : p.tree.barrels) {
    j.begin_object();
    j.key("sides");
    j.value(b.sides);
    j.key("operation");
    j.value(cooper::imprint_operation(b));
    for (int end = 0; end < 2; ++end) {
      j.key(end == 0 ? "upper" : "lower");
      j.begin_array();
      for (const cooper::EndPiece& e : end == 0 ? b.upper : b.lower) {
        j.begin_object();
        if (e.cap) {
          j.key("surface");
          j.value(e.cap);
          const auto it = p.roles.scheme.find(e.cap);
          j.key("meshed_by");
          j.value(it != p.roles.scheme.end() ? it->second : std::string("cooper"));
        } else {
          const cooper::BarrelInterface& v = p.tree.interfaces[static_cast<size_t>(e.interface)];
          j.key(end == 0 ? "virtual_from_barrel" : "virtual_into_barrel");
          j.value((end == 0 ? v.above : v.below) + 1);
        }
        j.end_object();
      }
      j.end_array();
    }
    j.end_object();
  }
  j.end_array();
  j.end_object();
}

void write_decomposition(const decompose::Report& cuts, JsonWriter& j) {
  const auto vec = [&](const geom::Vec3& v) {
    j.begin_array();
    for (int k = 0; k < 3; ++k) j.value(v[k]);
    j.end_array();
  };
  j.begin_object();
  j.key("tried");
  j.value(cuts.tried);
  j.key("volumes");
  j.begin_array();
  for (const auto& v : cuts.volumes) {
    j.begin_object();
    j.key("volume");
    j.value(v.volume);
    j.key("name");
    j.value(v.name);
    j.key("why");
    j.value(v.why);
    j.key("tried");
    j.value(v.tried);
    j.key("pieces");
    j.begin_array();
    for (int p : v.pieces) j.value(p);
    j.end_array();
    j.key("cuts");
    j.begin_array();
    for (const auto& c : v.cuts) {
      j.begin_object();
      j.key("kind");
      j.value(c.surface.kind == occ::CutSurface::Kind::Plane      ? "plane"
              : c.surface.kind == occ::CutSurface::Kind::Cylinder ? "cylinder"
                                                                  : "cone");
      j.key("origin");
      vec(c.surface.origin);
      j.key("direction");
      vec(c.surface.direction);
      if (c.surface.kind != occ::CutSurface::Kind::Plane) {
        j.key("radius");
        j.value(c.surface.radius);
      }
      if (c.surface.kind == occ::CutSurface::Kind::Cone) {
        j.key("half_angle_degrees");
        j.value(c.surface.half_angle * 180.0 / M_PI);
      }
      j.key("description");
      j.value(decompose::describe(c.surface));
      j.key("through");
      j.value(c.through);
      j.key("depth");
      j.value(c.depth);
      j.key("pieces");
      j.value(c.pieces);
      j.key("thinnest");
      j.value(c.thinnest);
      j.end_object();
    }
    j.end_array();
    j.end_object();
  }
  j.end_array();
  j.end_object();
}

// Every scheme's verdict: {scheme, ok, score, why} each.
void write_candidates(JsonWriter& j, const std::vector<selector::Candidate>& candidates) {
  j.key("candidates");
  j.begin_array();
  for (const auto& k : candidates) {
    j.begin_object();
    j.key("scheme");
    j.value(k.scheme);
    j.key("ok");
    j.value(k.applicability.ok);
    j.key("score");
    j.value(k.applicability.score);
    j.key("why");
    j.value(k.applicability.why);
    j.end_object();
  }
  j.end_array();
}

void write_json(const selector::Selection& sel, const decompose::Report& cuts,
                const std::string& decomposition_failed, bool intervals_checked,
                const geom::Model& model, const scheme::Registry& registry,
                const scheme::Settings& job, std::ostream& out) {
  JsonWriter j(out);
  auto entities = [&](const std::vector<selector::Choice>& list) {
    j.begin_array();
    for (const auto& c : list) {
      j.begin_object();
      j.key("id");
      j.value(c.id);
      j.key("scheme");
      j.value(c.scheme);
      j.key("reason");
      j.value(c.reason);
      j.key("pinned");
      j.value(c.pinned);
      if (const auto w = sel.waits_for.find(c.id); c.dim == 3 && w != sel.waits_for.end()) {
        j.key("meshed_after");
        j.value(w->second);
      }
      if (const auto p = cooper_plan(c); p && p->ok) {
        j.key("barrel_tree");
        write_barrel_tree(j, *p);
      }
      write_candidates(j, c.candidates);
      j.end_object();
    }
    j.end_array();
  };
  j.begin_object();
  j.key("decomposition");
  write_decomposition(cuts, j);
  j.key("decomposition_failed");
  j.value(decomposition_failed);
  j.key("volumes");
  entities(sel.volumes);
  j.key("refused_volumes");
  j.begin_array();
  for (const auto& [id, r] : sel.refused) {
    j.begin_object();
    j.key("id");
    j.value(id);
    j.key("reason");
    j.value(r.message);
    write_candidates(j, refused_candidates(id, model, registry, job));
    j.end_object();
  }
  j.end_array();
  j.key("surfaces");
  entities(sel.surfaces);
  j.key("relaxations");
  j.begin_array();
  for (const auto& r : sel.relaxations) j.value(r);
  j.end_array();
  j.key("intervals_checked");
  j.value(intervals_checked);
  j.end_object();
  out << "\n";
}

}  // namespace

int run_plan(const std::string& file, std::optional<io::ElementSize> size, bool json,
             const std::vector<std::string>& plugins, std::ostream& out, int dim,
             const pipeline::PlanOverrides& overrides) {
  // The decomposition's registry: the command line's plug-ins take part in
  // it (a journal's are known only once it is read).
  scheme::Registry defaults;
  register_schemes(defaults, run_plugins(plugins, {}));
  // A volume that no scheme fits and no cut helps is shown undecomposed,
  // with every scheme's full reason: what `plan` is for.
  pipeline::PlanInput input;
  std::string decomposition_failed;
  try {
    input = dim == 3 ? pipeline::plan_input(file, size, &defaults, selector::planner(), overrides)
                     : pipeline::plan_input(file, size, nullptr, {}, overrides);
  } catch (const MeshingError& e) {
    if (e.code() != ErrorCode::NotApplicable || e.entity().dim != 3) throw;
    decomposition_failed = "volume " + std::to_string(e.entity().id) + ": " + e.message();
    input = pipeline::plan_input(file, size, nullptr, {}, overrides);
  }
  const geom::Model& model = input.model;
  const io::MeshSettings& settings = input.settings;
  pipeline::check_elements_for_dim(settings, dim);
  pipeline::check_planned_size(model, settings, dim);  // as `mesh` refuses before planning
  scheme::Registry registry;
  register_schemes(registry, run_plugins(plugins, input.plugins));
  const scheme::Settings job = scheme::Settings::of(settings);
  selector::SelectOptions options;
  options.dim = dim;
  options.check_intervals = settings.size.has_value();
  // A volume no scheme fits is listed with every scheme's reason (what
  // `plan` is for); any other planning error stays an error.
  selector::Selection sel;
  try {
    sel = selector::select_schemes(model, registry, settings, options);
  } catch (const MeshingError& e) {
    if (e.code() != ErrorCode::NotApplicable || e.entity().dim != 3) throw;
    options.refuse_per_volume = true;
    sel = selector::select_schemes(model, registry, settings, options);
  }
  if (json) {
    write_json(sel, input.decomposition, decomposition_failed, options.check_intervals, model,
               registry, job, out);
  } else {
    write_text(sel, input.decomposition, decomposition_failed, options.check_intervals, model,
               registry, job, out);
  }
  for (const auto& [id, r] : sel.refused) {
    std::cerr << "cooperage: error: volume " << id << ": " << clip(r.message, kMaxRefusalLine)
              << "\n";
  }
  return sel.refused.empty() ? 0 : kExitRefused;
}

}  // namespace cooperage::app
