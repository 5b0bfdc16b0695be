#include "framework/report/report_from_run.h"

#include <map>

#include "framework/report/html_text.h"
#include "framework/scheme/scheme.h"

namespace cooperage::report {
namespace {

using quality::ElementType;

std::string entity_name(const geom::Model& model, int dim, int id) {
  std::string name = (dim == 3 ? "volume " : "surface ") + std::to_string(id);
  if (dim == 3 && id >= 1 && id <= static_cast<int>(model.volumes().size()) &&
      !model.volume(id).name.empty()) {
    name += " (" + model.volume(id).name + ")";
  }
  return name;
}

template <std::size_t N>
void add_block(ReportInput& in, const std::string& name, const std::string& part, ElementType type,
               const std::vector<std::array<int, N>>& elements, const std::string& scheme,
               std::optional<double> seconds) {
  if (elements.empty()) return;
  ElementBlock b;
  b.name = name;
  b.part = part;
  b.scheme = scheme;
  b.type = type;
  b.connectivity = elements.front().data();
  b.count = elements.size();
  b.stride = static_cast<int>(N);
  b.seconds = seconds;
  in.blocks.push_back(std::move(b));
}

std::string scheme_text(const std::string& scheme) {
  return scheme == scheme::kMeshedByVolume ? std::string("meshed by its volume") : scheme;
}

void add_plan(ReportInput& in, const geom::Model& model, const pipeline::SchemePlan& plan) {
  for (int dim : {3, 2}) {
    for (const auto& [id, entry] : dim == 3 ? plan.volumes : plan.surfaces) {
      in.plan.push_back(
          {entity_name(model, dim, id), scheme_text(entry.scheme), entry.reason, entry.details});
    }
  }
}

void add_notes(ReportInput& in, const pipeline::RunResult& run) {
  for (const auto& c : run.quality.checks) {
    std::string line = "quality check " + c.check.metric;
    if (c.check.min) line += " >= " + detail::format_number("%g", *c.check.min);
    if (c.check.max) line += " <= " + detail::format_number("%g", *c.check.max);
    line += ": " + std::to_string(c.violations) + " elements outside" +
            (c.failed ? ", FAILED" : (c.violations ? " (warning)" : ", ok"));
    in.notes.push_back(line);
  }
  for (const auto& f : run.written) in.notes.push_back("wrote " + f);
  if (run.exports_skipped) in.notes.push_back("exports skipped: a quality check failed");
}

}  // namespace

ReportInput report_input(const pipeline::RunResult& run, const std::string& title) {
  const mesh::MeshDB& db = run.mesh.mesh;
  const geom::Model& model = run.model;
  ReportInput in;
  in.title = title;
  in.coords = &db.coords();
  std::map<std::pair<int, int>, double> seconds;
  std::map<std::pair<int, int>, std::string> schemes;
  for (const auto& t : run.mesh.timings) {
    seconds[{t.dim, t.id}] = t.seconds;
    schemes[{t.dim, t.id}] = t.scheme;
  }
  auto time_of = [&](int dim, int id) -> std::optional<double> {
    const auto it = seconds.find({dim, id});
    return it == seconds.end() ? std::nullopt : std::optional<double>(it->second);
  };
  if (db.hex_count() + db.wedge_count() > 0) {
    for (const auto& [id, v] : db.volumes()) {
      const std::string name = entity_name(model, 3, id);
      add_block(in, name, name, ElementType::Hex, v.hexes, schemes[{3, id}], time_of(3, id));
      add_block(in, name, name, ElementType::Wedge, v.wedges, schemes[{3, id}], time_of(3, id));
    }
    in.maybe_boundary.resize(db.node_count());
    for (std::size_t i = 0; i < db.node_count(); ++i) {
      in.maybe_boundary[i] = db.owner(static_cast<int>(i)).dim < 3;
    }
  } else {
    for (const auto& [id, s] : db.surfaces()) {
      const std::string name = entity_name(model, 2, id);
      const geom::Surface& surface = model.surface(id);
      add_block(in, name, "all surfaces", ElementType::Quad, s.quads, schemes[{2, id}],
                time_of(2, id));
      if (!s.quads.empty())
        in.blocks.back().normals = pipeline::reference_normals(db, surface, s.quads);
      add_block(in, name, "all surfaces", ElementType::Tri, s.tris, schemes[{2, id}],
                time_of(2, id));
      if (!s.tris.empty())
        in.blocks.back().normals = pipeline::reference_normals(db, surface, s.tris);
    }
  }
  add_plan(in, model, run.mesh.plan);
  for (const auto& s : run.stages) in.stages.push_back({s.stage, s.seconds});
  for (const auto& w : run.mesh.warnings) in.warnings.push_back(w.text());
  add_notes(in, run);
  return in;
}

}  // namespace cooperage::report
