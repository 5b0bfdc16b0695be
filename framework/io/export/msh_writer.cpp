#include "framework/io/export/msh_writer.h"

#include "framework/core/error.h"
#include "framework/io/export/export_common.h"
#include "framework/io/export/mesh_groups.h"
#include "framework/io/export/stream_buffer.h"

#include <map>
#include <ostream>
#include <string_view>
#include <utility>
#include <vector>

namespace cooperage::io {
namespace {

using geom::BoundingBox;
using geom::Vec3;
using EntityKey = std::pair<int, int>;  // (dim, id)
using detail::StreamBuffer;

// Numbers of the Gmsh 4.1 format, as text (blank-separated, a line per
// record) or as binary values of the type the format names (int, size_t,
// double); section keywords and $PhysicalNames are text in both.
class MshOut {
 public:
  MshOut(StreamBuffer& out, bool binary) : out_(out), binary_(binary) {}
  bool binary() const { return binary_; }
  MshOut& i(int v) { return put(v); }
  MshOut& z(size_t v) { return put(v); }
  MshOut& d(double v) { return put(v); }
  /// End of a record (a line in ASCII; nothing in binary).
  void eol() {
    if (!binary_) out_ << '\n';
    first_ = true;
  }
  /// A text line; in binary mode a newline first ends the binary run.
  void line(std::string_view text) {
    if (binary_ && in_binary_) out_ << '\n';
    in_binary_ = false;
    out_ << text << '\n';
  }
  StreamBuffer& text() { return out_; }

 private:
  template <class T>
  MshOut& put(T v) {
    if (binary_) {
      out_.raw(v);
      in_binary_ = true;
    } else {
      if (!first_) out_ << ' ';
      out_ << v;
      first_ = false;
    }
    return *this;
  }
  StreamBuffer& out_;
  bool binary_;
  bool first_ = true, in_binary_ = false;
};

void write_box(MshOut& out, const BoundingBox& b) {
  const Vec3 lo = b.empty() ? Vec3::Zero() : b.min;
  const Vec3 hi = b.empty() ? Vec3::Zero() : b.max;
  out.d(lo.x()).d(lo.y()).d(lo.z()).d(hi.x()).d(hi.y()).d(hi.z());
}

// numPhysicalTags then the tags.
void write_physical(MshOut& out, const std::vector<int>& tags) {
  out.z(tags.size());
  for (int t : tags) out.i(t);
}

/// Physical groups: "dim tag \"name\"" lines, and each entity's tags.
struct Physicals {
  std::vector<std::string> names;
  std::map<EntityKey, std::vector<int>> tags;
  void add(int dim, int tag, const std::string& name, const std::vector<int>& entities) {
    names.push_back(std::to_string(dim) + " " + std::to_string(tag) + " \"" + name + "\"");
    for (int e : entities) tags[{dim, e}].push_back(tag);
  }
  const std::vector<int>& of(int dim, int id) const {
    static const std::vector<int> none;
    auto it = tags.find({dim, id});
    return it == tags.end() ? none : it->second;
  }
};

// Blocks and side sets as physical groups (mesh_groups.h): blocks of
// dimension 3 (2 in a surface-only mesh), side sets of dimension 2. Without
// named side sets, a volume mesh has a group per surface with elements.
Physicals physicals(const mesh::MeshDB& db, const detail::MeshGroups& groups) {
  Physicals p;
  const int block_dim = groups.volume_mesh ? 3 : 2;
  for (const auto& b : groups.blocks) p.add(block_dim, b.id, b.name, b.entities);
  if (!groups.volume_mesh) return p;
  if (groups.named_side_sets) {
    for (const auto& s : groups.side_sets) p.add(2, s.id, s.name, s.surfaces);
  } else {
    for (const auto& [sid, s] : db.surfaces())
      if (s.size() > 0) p.add(2, sid, "surface_" + std::to_string(sid), {sid});
  }
  return p;
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
  const int counts[4] = {
      static_cast<int>(model.vertices().size()), static_cast<int>(model.curves().size()),
      static_cast<int>(model.surfaces().size()), static_cast<int>(model.volumes().size())};
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
    for (const auto& e : v.hexes)
      for (int x : e) claim(x, 3, vid);
    for (const auto& e : v.wedges)
      for (int x : e) claim(x, 3, vid);
  }
  for (const auto& [sid, s] : db.surfaces()) {
    for (const auto& e : s.quads)
      for (int x : e) claim(x, 2, sid);
    for (const auto& e : s.tris)
      for (int x : e) claim(x, 2, sid);
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

void write_body(MshOut& out, const mesh::MeshDB& db, const geom::Model& model,
                const detail::MeshGroups& named) {
  out.line("$MeshFormat");
  if (out.binary()) {
    out.text() << "4.1 1 " << static_cast<int>(sizeof(size_t)) << '\n';
    out.i(1);  // lets a reader check the byte order
  } else {
    out.line("4.1 0 8");
  }
  out.line("$EndMeshFormat");

  // ---- physical names (text in both encodings) ----------------------------
  const Physicals physical = physicals(db, named);
  out.line("$PhysicalNames");
  out.line(std::to_string(physical.names.size()));
  for (const auto& p : physical.names) out.line(p);
  out.line("$EndPhysicalNames");

  // ---- entities --------------------------------------------------------------
  const auto owner = node_entities(db, model);
  out.line("$Entities");
  out.z(model.vertices().size())
      .z(model.curves().size())
      .z(model.surfaces().size())
      .z(model.volumes().size());
  out.eol();
  for (const auto& v : model.vertices()) {
    const int node = db.vertex_node(v.id);
    const Vec3 p = node >= 0 && node < static_cast<int>(db.node_count()) ? db.node(node) : v.point;
    out.i(v.id).d(p.x()).d(p.y()).d(p.z()).z(0);
    out.eol();
  }
  for (const auto& c : model.curves()) {
    BoundingBox b;
    for (int v : db.curve_nodes(c.id)) {
      if (v >= 0 && v < static_cast<int>(db.node_count())) b.add(db.node(v));
    }
    std::vector<int> ends;
    if (c.start_vertex > 0) ends.push_back(c.start_vertex);
    if (c.end_vertex > 0 && c.end_vertex != c.start_vertex) ends.push_back(-c.end_vertex);
    out.i(c.id);
    write_box(out, b);
    out.z(0).z(ends.size());
    for (int e : ends) out.i(e);
    out.eol();
  }
  for (const auto& s : model.surfaces()) {
    BoundingBox b;
    const auto& m = db.surface(s.id);
    add_nodes(b, m.quads, db);
    add_nodes(b, m.tris, db);
    if (b.empty()) b = s.box;
    std::vector<int> bounding;
    for (const auto& loop : s.loops) {
      for (const auto& u : loop.uses)
        bounding.push_back(u.curve * static_cast<int>(geom::sign(u.sense)));
    }
    out.i(s.id);
    write_box(out, b);
    write_physical(out, physical.of(2, s.id));
    out.z(bounding.size());
    for (int c : bounding) out.i(c);
    out.eol();
  }
  for (const auto& v : model.volumes()) {
    BoundingBox b;
    const auto& m = db.volume(v.id);
    add_nodes(b, m.hexes, db);
    add_nodes(b, m.wedges, db);
    if (b.empty()) b = v.box;
    std::vector<int> bounding;
    for (const auto& shell : v.shells) {
      for (const auto& u : shell)
        bounding.push_back(u.surface * static_cast<int>(geom::sign(u.sense)));
    }
    out.i(v.id);
    write_box(out, b);
    write_physical(out, physical.of(3, v.id));
    out.z(bounding.size());
    for (int s : bounding) out.i(s);
    out.eol();
  }
  out.line("$EndEntities");

  // ---- nodes -------------------------------------------------------------------
  std::map<EntityKey, std::vector<int>> groups;
  for (size_t i = 0; i < owner.size(); ++i) groups[owner[i]].push_back(static_cast<int>(i));
  const size_t n = db.node_count();
  out.line("$Nodes");
  out.z(groups.size()).z(n).z(n > 0 ? 1 : 0).z(n);
  out.eol();
  for (const auto& [key, nodes] : groups) {
    out.i(key.first).i(key.second).i(0).z(nodes.size());
    out.eol();
    for (int v : nodes) {
      out.z(static_cast<size_t>(v) + 1);
      out.eol();
    }
    for (int v : nodes) {
      const Vec3& p = db.node(v);
      out.d(p.x()).d(p.y()).d(p.z());
      out.eol();
    }
  }
  out.line("$EndNodes");

  // ---- elements ------------------------------------------------------------------
  // Only the elements of entities in a physical group: Gmsh writes no others
  // when groups exist, and meshio refuses a file with some elements outside
  // every group. (By default every entity with elements is in one.)
  const auto in_group = [&](int dim, int id) { return !physical.of(dim, id).empty(); };
  size_t blocks = 0, total = 0;
  for (const auto& [vid, v] : db.volumes()) {
    if (!in_group(3, vid)) continue;
    blocks += !v.hexes.empty() + !v.wedges.empty();
    total += v.size();
  }
  for (const auto& [sid, s] : db.surfaces()) {
    if (!in_group(2, sid)) continue;
    blocks += !s.quads.empty() + !s.tris.empty();
    total += s.size();
  }
  out.line("$Elements");
  out.z(blocks).z(total).z(total > 0 ? 1 : 0).z(total);
  out.eol();
  size_t tag = 1;
  auto block = [&](int dim, int id, int type, const auto& elems) {
    if (elems.empty() || !in_group(dim, id)) return;
    out.i(dim).i(id).i(type).z(elems.size());
    out.eol();
    for (const auto& e : elems) {
      out.z(tag++);
      for (int v : e) out.z(static_cast<size_t>(v) + 1);
      out.eol();
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
  out.line("$EndElements");
}

}  // namespace

void write_msh(const std::string& path, const mesh::MeshDB& db, const geom::Model& model,
               const ExportOptions& options) {
  detail::validate_mesh(db, model);
  const detail::MeshGroups groups = detail::mesh_groups(db, model, options);
  detail::write_text_atomically(path, [&](std::ostream& os) {
    StreamBuffer buffer(os);
    MshOut out(buffer, options.binary);
    write_body(out, db, model, groups);
  });
}

}  // namespace cooperage::io
