#include "framework/io/export/mesh_groups.h"

#include "framework/core/error.h"
#include "framework/io/export/export_common.h"

#include <algorithm>
#include <set>

namespace cooperage::io::detail {
namespace {

std::string at(const SourceLocation& where) {
  if (where.line <= 0) return {};
  return where.file + ":" + std::to_string(where.line) + ": <" + where.element + ">: ";
}

std::string quoted(const char* kind, int id, const std::string& name) {
  return std::string(kind) + " " + std::to_string(id) + " \"" + name + "\"";
}

bool volume_has_elements(const mesh::MeshDB& db, int id) {
  return db.volume_meshed(id) && db.volume(id).size() > 0;
}
bool surface_has_elements(const mesh::MeshDB& db, int id) {
  return db.surface_meshed(id) && db.surface(id).size() > 0;
}
// A surface whose elements are faces of its first volume's elements.
bool surface_has_faces(const mesh::MeshDB& db, const geom::Model& model, int id) {
  const auto& vols = model.surface(id).volumes;
  return surface_has_elements(db, id) && !vols.empty() && volume_has_elements(db, vols.front());
}

// Empty group: an error naming the line, or left out (skip_empty_groups).
bool keep(bool has_elements, const ExportOptions& options, const SourceLocation& where,
          const std::string& what, const std::string& why) {
  if (has_elements) return true;
  if (options.skip_empty_groups) return false;
  throw MeshingError(ErrorCode::InvalidInput, at(where) + what + ": " + why);
}

std::vector<MeshBlock> user_blocks(const mesh::MeshDB& db, bool volume_mesh,
                                   const ExportOptions& options) {
  std::vector<MeshBlock> out;
  std::set<int> covered;
  for (const BlockSetting& b : options.groups.blocks) {
    const std::string what = quoted("block", b.id, b.name);
    const auto& listed = volume_mesh ? b.volumes : b.surfaces;
    if (listed.empty())
      throw MeshingError(ErrorCode::InvalidInput,
                         at(b.where) + what +
                             (volume_mesh ? " lists surfaces, but the mesh has volume elements: "
                                            "a block of a volume mesh takes volumes=\"...\""
                                          : " lists volumes, but the mesh has surface elements "
                                            "only (--dim 2): give the block surfaces=\"...\""));
    MeshBlock m{b.id, b.name, {}};
    for (int id : listed) {
      if (volume_mesh ? volume_has_elements(db, id) : surface_has_elements(db, id))
        m.entities.push_back(id);
    }
    std::sort(m.entities.begin(), m.entities.end());
    covered.insert(m.entities.begin(), m.entities.end());
    if (keep(
            !m.entities.empty(), options, b.where, what,
            std::string("none of its ") + (volume_mesh ? "volumes" : "surfaces") + " has elements"))
      out.push_back(std::move(m));
  }
  // Every element in a block: an element left out of every block would
  // silently vanish from the solver's model.
  auto check = [&](int id, const char* kind) {
    if (!covered.count(id))
      throw MeshingError(ErrorCode::InvalidInput,
                         at(options.groups.blocks.front().where) + std::string(kind) + " " +
                             std::to_string(id) +
                             " has elements but is in no <block>; add it to one (when a "
                             "journal names blocks, every element belongs to one)");
  };
  if (volume_mesh) {
    for (const auto& [id, v] : db.volumes())
      if (v.size() > 0) check(id, "volume");
  } else {
    for (const auto& [id, s] : db.surfaces())
      if (s.size() > 0) check(id, "surface");
  }
  return out;
}

std::vector<int> node_set_nodes(const mesh::MeshDB& db, const NodeSetSetting& n) {
  std::vector<int> nodes;
  for (int s : n.surfaces) {
    if (!db.surface_meshed(s)) continue;
    const auto more = surface_node_set(db.surface(s));
    nodes.insert(nodes.end(), more.begin(), more.end());
  }
  for (int c : n.curves) {
    if (!db.curve_meshed(c)) continue;
    const auto& chain = db.curve_nodes(c);
    nodes.insert(nodes.end(), chain.begin(), chain.end());
  }
  for (int v : n.vertices) {
    const int node = db.vertex_node(v);
    if (node >= 0) nodes.push_back(node);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace

MeshGroups mesh_groups(const mesh::MeshDB& db, const geom::Model& model,
                       const ExportOptions& options) {
  const GroupSettings& given = options.groups;
  MeshGroups g;
  g.volume_mesh = has_volume_elements(db);
  g.named_blocks = !given.blocks.empty();
  g.named_side_sets = !given.side_sets.empty();
  g.named_node_sets = !given.node_sets.empty();

  // ---- blocks ----
  if (g.named_blocks) {
    g.blocks = user_blocks(db, g.volume_mesh, options);
  } else if (g.volume_mesh) {
    for (const auto& [id, v] : db.volumes())
      if (v.size() > 0) g.blocks.push_back({id, volume_label(model, id), {id}});
  } else {
    for (const auto& [id, s] : db.surfaces())
      if (s.size() > 0) g.blocks.push_back({id, "surface_" + std::to_string(id), {id}});
  }

  // ---- side sets (volume meshes) ----
  if (g.volume_mesh && g.named_side_sets) {
    for (const SideSetSetting& s : given.side_sets) {
      MeshSideSet m{s.id, s.name, {}};
      for (int id : s.surfaces)
        if (surface_has_faces(db, model, id)) m.surfaces.push_back(id);
      std::sort(m.surfaces.begin(), m.surfaces.end());
      if (keep(!m.surfaces.empty(), options, s.where, quoted("side set", s.id, s.name),
               "none of its surfaces carries faces of volume elements"))
        g.side_sets.push_back(std::move(m));
    }
  } else if (g.volume_mesh) {
    for (const auto& [id, s] : db.surfaces())
      if (surface_has_faces(db, model, id))
        g.side_sets.push_back({id, "surface_" + std::to_string(id), {id}});
  }

  // ---- node sets ----
  if (g.named_node_sets) {
    for (const NodeSetSetting& n : given.node_sets) {
      MeshNodeSet m{n.id, n.name, node_set_nodes(db, n)};
      if (keep(!m.nodes.empty(), options, n.where, quoted("node set", n.id, n.name),
               "none of its entities has nodes"))
        g.node_sets.push_back(std::move(m));
    }
  } else {
    for (const auto& [id, s] : db.surfaces())
      if (s.size() > 0)
        g.node_sets.push_back({id, "surface_" + std::to_string(id), surface_node_set(s)});
  }
  return g;
}

}  // namespace cooperage::io::detail
