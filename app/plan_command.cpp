#include "plan_command.h"

#include "json_writer.h"

#include "framework/decompose/report_text.h"
#include "framework/pipeline/model_job.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

namespace cooperage::app {
namespace {

void write_text(const selector::Selection& sel, const decompose::Report& cuts,
                bool intervals_checked, std::ostream& out) {
  auto entity = [&](const selector::Choice& c) {
    out << (c.dim == 3 ? "volume " : "surface ") << c.id << ": "
        << (c.scheme == scheme::kMeshedByVolume ? std::string("meshed by its volume") : c.scheme)
        << "  -- " << c.reason << "\n";
    for (const auto& k : c.candidates) out << "    " << selector::describe(k) << "\n";
  };
  const std::vector<std::string> cut_lines = decompose::report_lines(cuts);
  if (!cut_lines.empty()) {
    out << "decomposition (" << cuts.tried << " cuts tried)\n";
    for (const auto& line : cut_lines) out << "  " << line << "\n";
  }
  if (!sel.volumes.empty()) out << "volumes\n";
  for (const auto& c : sel.volumes) entity(c);
  out << "surfaces\n";
  for (const auto& c : sel.surfaces) entity(c);
  for (const auto& r : sel.relaxations) out << "relaxed " << r << "\n";
  if (!intervals_checked) out << "interval feasibility not checked: no element size given\n";
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
      j.value(c.surface.kind == occ::CutSurface::Kind::Plane ? "plane" : "cylinder");
      j.key("origin");
      vec(c.surface.origin);
      j.key("direction");
      vec(c.surface.direction);
      if (c.surface.kind == occ::CutSurface::Kind::Cylinder) {
        j.key("radius");
        j.value(c.surface.radius);
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

void write_json(const selector::Selection& sel, const decompose::Report& cuts,
                bool intervals_checked, std::ostream& out) {
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
      j.key("candidates");
      j.begin_array();
      for (const auto& k : c.candidates) {
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
      j.end_object();
    }
    j.end_array();
  };
  j.begin_object();
  j.key("decomposition");
  write_decomposition(cuts, j);
  j.key("volumes");
  entities(sel.volumes);
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

int run_plan(const std::string& file, std::optional<double> size, bool json, std::ostream& out) {
  // Decomposition only happens for jobs without per-entity settings, for
  // which the default scheme options are the job's own.
  scheme::Registry defaults;
  register_builtin_schemes(defaults);
  const pipeline::PlanInput input =
      pipeline::plan_input(file, size, &defaults, selector::planner());
  const geom::Model& model = input.model;
  const io::MeshSettings& settings = input.settings;
  scheme::Registry registry;
  register_builtin_schemes(registry, builtin_options(settings));
  selector::SelectOptions options;
  options.check_intervals = settings.size.has_value();
  const selector::Selection sel = selector::select_schemes(model, registry, settings, options);
  if (json) {
    write_json(sel, input.decomposition, options.check_intervals, out);
  } else {
    write_text(sel, input.decomposition, options.check_intervals, out);
  }
  return 0;
}

}  // namespace cooperage::app
