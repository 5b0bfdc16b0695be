#include "framework/pipeline/check_settings.h"

#include "framework/core/error.h"
#include "framework/io/journal_xml.h"

#include <algorithm>
#include <cctype>
#include <map>

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

void check_elements_for_dim(const io::MeshSettings& settings, int dim) {
  if (dim != 2 || settings.elements == io::ElementKind::Hex) return;
  const char* kind = settings.elements == io::ElementKind::Wedge ? "wedge" : "mixed";
  throw MeshingError(ErrorCode::InvalidInput, EntityRef::none(),
                     std::string("elements \"") + kind +
                         "\" asks for volume elements, but a surface mesh (dim 2) has none",
                     "mesh in 3D, or give the surfaces scheme \"tri\" or \"quad_dominant\" in a "
                     "journal (<surface id scheme>) for triangles on a surface mesh");
}

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
    const io::ElementKind elements = v.elements.value_or(settings.elements);
    if (elements != io::ElementKind::Hex && v.scheme == "map") {
      const char* kind = elements == io::ElementKind::Wedge ? "wedge" : "mixed";
      throw MeshingError(ErrorCode::InvalidInput,
                         at(v.where) + "elements=\"" + kind +
                             "\" with scheme=\"map\": a volume map "
                             "makes hexes only; use scheme=\"cooper\" or \"auto\"");
    }
  }
  for (const auto& p : settings.vertex_types) {
    check_id(p.where, "surface", p.surface, model.surfaces().size());
    check_id(p.where, "vertex", p.vertex, model.vertices().size());
  }
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

[[noreturn]] void group_error(const io::SourceLocation& where, const std::string& message) {
  throw MeshingError(
      ErrorCode::InvalidInput,
      (where.line > 0 ? at(where) : where.file + ": " + where.element + ": ") + message);
}

// What the journal reader checks per element (journal_groups.cpp), for
// groups built in code (cooperage::Options::groups): ids and names unique
// per kind, names the formats keep, an entity in one block.
template <class Setting>
void check_kind(const std::vector<Setting>& all, const char* kind) {
  for (size_t i = 0; i < all.size(); ++i) {
    const Setting& g = all[i];
    if (g.id < 1)
      group_error(g.where, std::string(kind) + " id " + std::to_string(g.id) + " is not positive");
    const bool name_ok = !g.name.empty() && g.name.size() <= 32 &&
                         std::isalpha(static_cast<unsigned char>(g.name[0])) &&
                         std::all_of(g.name.begin(), g.name.end(), [](char c) {
                           return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                         });
    if (!name_ok)
      group_error(g.where, std::string(kind) + " " + std::to_string(g.id) + ": the name \"" +
                               g.name.substr(0, 40) +
                               "\" must be a letter, then letters, digits "
                               "or '_' (at most 32 characters)");
    for (size_t j = 0; j < i; ++j) {
      if (all[j].id == g.id)
        group_error(g.where, std::string(kind) + " id " + std::to_string(g.id) + " is used twice");
      if (lower(all[j].name) == lower(g.name))
        group_error(g.where, std::string(kind) + " name \"" + g.name + "\" is used twice");
    }
  }
}

}  // namespace

void check_groups(const geom::Model& model, const io::GroupSettings& groups) {
  check_kind(groups.blocks, "block");
  check_kind(groups.side_sets, "side set");
  check_kind(groups.node_sets, "node set");
  std::map<std::pair<int, int>, int> block_of;  // (dim, id) -> block
  for (const auto& b : groups.blocks) {
    if (b.volumes.empty() == b.surfaces.empty())
      group_error(b.where, "block " + std::to_string(b.id) +
                               " needs exactly one of volumes (a volume mesh) and surfaces (a "
                               "surface mesh)");
    for (int dim : {3, 2}) {
      for (int id : dim == 3 ? b.volumes : b.surfaces) {
        auto [it, fresh] = block_of.emplace(std::make_pair(dim, id), b.id);
        if (!fresh)
          group_error(b.where, std::string(dim == 3 ? "volume " : "surface ") + std::to_string(id) +
                                   " is in blocks " + std::to_string(it->second) + " and " +
                                   std::to_string(b.id) + "; an element belongs to one block");
      }
    }
  }
  for (const auto& s : groups.side_sets)
    if (s.surfaces.empty())
      group_error(s.where, "side set " + std::to_string(s.id) + " has no surfaces");
  for (const auto& n : groups.node_sets)
    if (n.surfaces.empty() && n.curves.empty() && n.vertices.empty())
      group_error(n.where,
                  "node set " + std::to_string(n.id) + " has no surfaces, curves or vertices");
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
