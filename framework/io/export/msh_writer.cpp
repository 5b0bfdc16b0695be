#include "framework/io/export/msh_writer.h"

#include "framework/core/error.h"
#include "framework/io/export/export_common.h"

#include <map>
#include <ostream>
#include <utility>
#include <vector>

namespace cooperage::io {
namespace {

using geom::BoundingBox;
using geom::Vec3;
using EntityKey = std::pair<int, int>;  // (dim, id)

void write_box(std::ostream& out, const BoundingBox& b) {
  const Vec3 lo = b.empty() ? Vec3::Zero() : b.min;
  const Vec3 hi = b.empty() ? Vec3::Zero() : b.max;
  out << lo.x() << ' ' << lo.y() << ' ' << lo.z() << ' ' << hi.x() << ' ' << hi.y() << ' '
      << hi.z();
}

void write_physical(std::ostream& out, bool has) {
  out << (has ? " 1 " : " 0");
}

template <size_t N>
void add_nodes(BoundingBox& b, const std::vector<std::array<int, N>>& elems,
               const mesh::MeshDB& db) {
  for (const auto& e : elems) {
    for (int v : e) b.add(db.node(v));
  }
}

/// Owner entity of every node, per the rules in msh_writer.h.
std::vector<EntityKey> node_entities(const mesh::MeshDB& db, const geom::Model& model) {
  const int counts[4] = {static_cast<int>(model.vertices().size()),
                         static_cast<int>(model.curves().size()),
                         static_cast<int>(model.surfaces().size()),
                         static_cast<int>(model.volumes().size())};
  const size_t n = db.node_count();
  std::vector<EntityKey> key(n, EntityKey{-1, 0});
  for (size_t i = 0; i < n; ++i) {
    const auto& o = db.owner(static_cast<int>(i));
    if (o.dim >= 0 && o.dim <= 3 && o.id >= 1 && o.id <= counts[o.dim]) key[i] = {o.dim, o.id};
  }
  auto claim = [&](int v, int dim, int id) {
    auto& k = key[static_cast<size_t>(v)];
    if (k.first < 0) k = {dim, id};
  };
  for (const auto& [vid, v] : db.volumes()) {
    for (const auto& e : v.hexes) for (int x : e) claim(x, 3, vid);
    for (const auto& e : v.wedges) for (int x : e) claim(x, 3, vid);
  }
  for (const auto& [sid, s] : db.surfaces()) {
    for (const auto& e : s.quads) for (int x : e) claim(x, 2, sid);
    for (const auto& e : s.tris) for (int x : e) claim(x, 2, sid);
  }
  EntityKey fallback{-1, 0};
  for (int d = 3; d >= 0 && fallback.first < 0; --d) {
    if (counts[d] > 0) fallback = {d, 1};
  }
  for (auto& k : key) {
    if (k.first >= 0) continue;
    if (fallback.first < 0) {
      throw MeshingError(ErrorCode::InvalidInput, "Gmsh export needs a model with entities");
    }
    k = fallback;
  }
  return key;
}

void write_body(std::ostream& out, const mesh::MeshDB& db, const geom::Model& model) {
  out.precision(17);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

  // ---- physical names ------------------------------------------------------
  std::vector<std::string> physical;
  for (const auto& [vid, v] : db.volumes()) {
    if (v.size() > 0) {
      physical.push_back("3 " + std::to_string(vid) + " \"" + detail::volume_label(model, vid) + "\"");
    }
  }
  for (const auto& [sid, s] : db.surfaces()) {
    if (s.size() > 0) {
      physical.push_back("2 " + std::to_string(sid) + " \"surface_" + std::to_string(sid) + "\"");
    }
  }
  out << "$PhysicalNames\n" << physical.size() << '\n';
  for (const auto& p : physical) out << p << '\n';
  out << "$EndPhysicalNames\n";

  // ---- entities --------------------------------------------------------------
  const auto owner = node_entities(db, model);
  out << "$Entities\n"
      << model.vertices().size() << ' ' << model.curves().size() << ' '
      << model.surfaces().size() << ' ' << model.volumes().size() << '\n';
  for (const auto& v : model.vertices()) {
    const int node = db.vertex_node(v.id);
    const Vec3 p = node >= 0 && node < static_cast<int>(db.node_count()) ? db.node(node) : v.point;
    out << v.id << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << " 0\n";
  }
  for (const auto& c : model.curves()) {
    BoundingBox b;
    for (int v : db.curve_nodes(c.id)) {
      if (v >= 0 && v < static_cast<int>(db.node_count())) b.add(db.node(v));
    }
    std::vector<int> ends;
    if (c.start_vertex > 0) ends.push_back(c.start_vertex);
    if (c.end_vertex > 0 && c.end_vertex != c.start_vertex) ends.push_back(-c.end_vertex);
    out << c.id << ' ';
    write_box(out, b);
    out << " 0 " << ends.size();
    for (int e : ends) out << ' ' << e;
    out << '\n';
  }
  for (const auto& s : model.surfaces()) {
    BoundingBox b;
    const auto& m = db.surface(s.id);
    add_nodes(b, m.quads, db);
    add_nodes(b, m.tris, db);
    if (b.empty()) b = s.box;
    std::vector<int> bounding;
    for (const auto& loop : s.loops) {
      for (const auto& u : loop.uses) bounding.push_back(u.curve * static_cast<int>(geom::sign(u.sense)));
    }
    out << s.id << ' ';
    write_box(out, b);
    write_physical(out, m.size() > 0);
    if (m.size() > 0) out << s.id;
    out << ' ' << bounding.size();
    for (int c : bounding) out << ' ' << c;
    out << '\n';
  }
  for (const auto& v : model.volumes()) {
    BoundingBox b;
    const auto& m = db.volume(v.id);
    add_nodes(b, m.hexes, db);
    add_nodes(b, m.wedges, db);
    if (b.empty()) b = v.box;
    std::vector<int> bounding;
    for (const auto& shell : v.shells) {
      for (const auto& u : shell) bounding.push_back(u.surface * static_cast<int>(geom::sign(u.sense)));
    }
    out << v.id << ' ';
    write_box(out, b);
    write_physical(out, m.size() > 0);
    if (m.size() > 0) out << v.id;
    out << ' ' << bounding.size();
    for (int s : bounding) out << ' ' << s;
    out << '\n';
  }
  out << "$EndEntities\n";

  // ---- nodes -------------------------------------------------------------------
  std::map<EntityKey, std::vector<int>> groups;
  for (size_t i = 0; i < owner.size(); ++i) groups[owner[i]].push_back(static_cast<int>(i));
  const size_t n = db.node_count();
  out << "$Nodes\n" << groups.size() << ' ' << n << ' ' << (n > 0 ? 1 : 0) << ' ' << n << '\n';
  for (const auto& [key, nodes] : groups) {
    out << key.first << ' ' << key.second << " 0 " << nodes.size() << '\n';
    for (int v : nodes) out << v + 1 << '\n';
    for (int v : nodes) {
      const Vec3& p = db.node(v);
      out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
  }
  out << "$EndNodes\n";

  // ---- elements ------------------------------------------------------------------
  size_t blocks = 0, total = 0;
  for (const auto& [vid, v] : db.volumes()) {
    blocks += !v.hexes.empty() + !v.wedges.empty();
    total += v.size();
  }
  for (const auto& [sid, s] : db.surfaces()) {
    blocks += !s.quads.empty() + !s.tris.empty();
    total += s.size();
  }
  out << "$Elements\n" << blocks << ' ' << total << ' ' << (total > 0 ? 1 : 0) << ' ' << total << '\n';
  size_t tag = 1;
  auto block = [&](int dim, int id, int type, const auto& elems) {
    if (elems.empty()) return;
    out << dim << ' ' << id << ' ' << type << ' ' << elems.size() << '\n';
    for (const auto& e : elems) {
      out << tag++;
      for (int v : e) out << ' ' << v + 1;
      out << '\n';
    }
  };
  for (const auto& [vid, v] : db.volumes()) {
    block(3, vid, 5, v.hexes);
    block(3, vid, 6, v.wedges);
  }
  for (const auto& [sid, s] : db.surfaces()) {
    block(2, sid, 3, s.quads);
    block(2, sid, 2, s.tris);
  }
  out << "$EndElements\n";
}

}  // namespace

void write_msh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
               const ExportOptions& options) {
  detail::validate_mesh(db, model);
  detail::write_text_atomically(path, [&](std::ostream& out) { write_body(out, db, model); });
}

}  // namespace cooperage::io
