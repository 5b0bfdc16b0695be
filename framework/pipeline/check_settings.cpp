#include "framework/pipeline/check_settings.h"

#include "framework/core/error.h"
#include "framework/io/journal_xml.h"

namespace cooperage::pipeline {
namespace {

std::string at(const io::SourceLocation& where) {
  return where.file + ":" + std::to_string(where.line) + ": <" + where.element + ">: ";
}

void check_id(const io::SourceLocation& where, const char* kind, int id, size_t count) {
  if (id < 1 || static_cast<size_t>(id) > count) {
    throw MeshingError(ErrorCode::InvalidInput,
                       at(where) + "the model has no " + kind + " " + std::to_string(id) +
                           " (it has " + std::to_string(count) + "; see `cooperage info`)");
  }
}

}  // namespace

void check_settings(const geom::Model& model, const io::MeshSettings& settings) {
  for (const auto& c : settings.curves) check_id(c.where, "curve", c.id, model.curves().size());
  for (const auto& s : settings.surfaces) {
    check_id(s.where, "surface", s.id, model.surfaces().size());
    if (s.sizing.intervals) {
      throw MeshingError(ErrorCode::InvalidInput,
                         at(s.where) + "intervals are set on curves; use size on a surface");
    }
  }
  for (const auto& v : settings.volumes) {
    check_id(v.where, "volume", v.id, model.volumes().size());
    if (v.sizing.intervals) {
      throw MeshingError(ErrorCode::InvalidInput,
                         at(v.where) + "intervals are set on curves; use size on a volume");
    }
    for (int s : v.sources) check_id(v.where, "surface", s, model.surfaces().size());
    for (int s : v.targets) check_id(v.where, "surface", s, model.surfaces().size());
    if (v.elements != io::ElementKind::Hex && v.scheme == "map") {
      const char* kind = v.elements == io::ElementKind::Wedge ? "wedge" : "mixed";
      throw MeshingError(ErrorCode::InvalidInput,
                         at(v.where) + "elements=\"" + kind + "\" with scheme=\"map\": a volume map "
                                       "makes hexes only; use scheme=\"cooper\" or \"auto\"");
    }
  }
  for (const auto& p : settings.vertex_types) {
    check_id(p.where, "surface", p.surface, model.surfaces().size());
    check_id(p.where, "vertex", p.vertex, model.vertices().size());
  }
}

void check_groups(const geom::Model& model, const io::GroupSettings& groups) {
  const size_t n_vol = model.volumes().size(), n_surf = model.surfaces().size();
  for (const auto& b : groups.blocks) {
    for (int v : b.volumes) check_id(b.where, "volume", v, n_vol);
    for (int s : b.surfaces) check_id(b.where, "surface", s, n_surf);
  }
  for (const auto& s : groups.side_sets)
    for (int id : s.surfaces) check_id(s.where, "surface", id, n_surf);
  for (const auto& n : groups.node_sets) {
    for (int id : n.surfaces) check_id(n.where, "surface", id, n_surf);
    for (int id : n.curves) check_id(n.where, "curve", id, model.curves().size());
    for (int id : n.vertices) check_id(n.where, "vertex", id, model.vertices().size());
  }
}

namespace {

void check_scheme_name(const io::SourceLocation& where, int dim, const std::string& name,
                       const scheme::Registry& registry) {
  if (name == "auto" || !registry.origin(dim, name).empty()) return;
  const std::vector<std::string> names = registry.names(dim);
  const char* kind = dim == 3 ? "volume" : "surface";
  throw MeshingError(ErrorCode::InvalidInput,
                     at(where) + "no " + kind + " scheme \"" + name + "\" is registered" +
                         io::detail::suggestion(name, names, "\"", "\"") + "; registered: " +
                         io::detail::list(names) + " (plug-ins add more: --plugin, <plugin>)");
}

}  // namespace

void check_scheme_names(const io::MeshSettings& settings, const scheme::Registry& registry) {
  for (const auto& s : settings.surfaces) check_scheme_name(s.where, 2, s.scheme, registry);
  for (const auto& v : settings.volumes) check_scheme_name(v.where, 3, v.scheme, registry);
}

}  // namespace cooperage::pipeline
