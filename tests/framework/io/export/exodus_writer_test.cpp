// Exodus II export, read back with the Exodus C library itself.
#include "framework/io/export/exodus_writer.h"

#include "export_fixtures.h"
#include "export_test_util.h"

#include <exodusII.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace cooperage::test {
namespace {

struct ExoBlock {
  std::string type, name;
  int count = 0, nodes_per = 0;
  std::vector<int> conn;
};

struct ExoFile {
  int dim = 0, nodes = 0, elems = 0, n_blocks = 0, n_node_sets = 0, n_side_sets = 0;
  std::vector<double> x, y, z;
  std::vector<int> block_ids;
  std::map<int, ExoBlock> blocks;
  std::vector<std::vector<int>> elements;  // global 1-based element -> 1-based nodes
  std::map<int, std::pair<std::vector<int>, std::vector<int>>> side_sets;  // id -> (elems, sides)
  std::map<int, std::vector<int>> node_sets;
};

std::vector<std::string> get_names(int exo, ex_entity_type type, int n) {
  std::vector<std::vector<char>> buf(static_cast<size_t>(n), std::vector<char>(257, '\0'));
  std::vector<char*> ptrs;
  for (auto& b : buf) ptrs.push_back(b.data());
  EXPECT_GE(ex_get_names(exo, type, ptrs.data()), 0);
  std::vector<std::string> names;
  for (auto& b : buf) names.emplace_back(b.data());
  return names;
}

ExoFile read_exodus(const std::string& path) {
  ExoFile f;
  int cpu_ws = 8, io_ws = 0;
  float version = 0;
  const int exo = ex_open(path.c_str(), EX_READ, &cpu_ws, &io_ws, &version);
  EXPECT_GE(exo, 0) << path;
  if (exo < 0) return f;
  char title[MAX_LINE_LENGTH + 1];
  EXPECT_GE(ex_get_init(exo, title, &f.dim, &f.nodes, &f.elems, &f.n_blocks, &f.n_node_sets,
                        &f.n_side_sets),
            0);
  EXPECT_EQ(io_ws, 8) << "coordinates are stored as doubles";
  f.x.resize(f.nodes);
  f.y.resize(f.nodes);
  f.z.resize(f.nodes);
  EXPECT_GE(ex_get_coord(exo, f.x.data(), f.y.data(), f.z.data()), 0);
  f.block_ids.resize(f.n_blocks);
  if (f.n_blocks) {
    EXPECT_GE(ex_get_ids(exo, EX_ELEM_BLOCK, f.block_ids.data()), 0);
  }
  const auto names = get_names(exo, EX_ELEM_BLOCK, f.n_blocks);
  for (int i = 0; i < f.n_blocks; ++i) {
    ExoBlock b;
    char type[MAX_STR_LENGTH + 1];
    int edges = 0, faces = 0, attrs = 0;
    EXPECT_GE(ex_get_block(exo, EX_ELEM_BLOCK, f.block_ids[i], type, &b.count, &b.nodes_per, &edges,
                           &faces, &attrs),
              0);
    b.type = type;
    b.name = names[i];
    b.conn.resize(static_cast<size_t>(b.count * b.nodes_per));
    EXPECT_GE(ex_get_conn(exo, EX_ELEM_BLOCK, f.block_ids[i], b.conn.data(), nullptr, nullptr), 0);
    for (int e = 0; e < b.count; ++e) {
      f.elements.emplace_back(b.conn.begin() + e * b.nodes_per,
                              b.conn.begin() + (e + 1) * b.nodes_per);
    }
    f.blocks[f.block_ids[i]] = b;
  }
  std::vector<int> ids(f.n_side_sets);
  if (f.n_side_sets) {
    EXPECT_GE(ex_get_ids(exo, EX_SIDE_SET, ids.data()), 0);
  }
  for (int id : ids) {
    int n = 0, df = 0;
    EXPECT_GE(ex_get_set_param(exo, EX_SIDE_SET, id, &n, &df), 0);
    auto& s = f.side_sets[id];
    s.first.resize(n);
    s.second.resize(n);
    EXPECT_GE(ex_get_set(exo, EX_SIDE_SET, id, s.first.data(), s.second.data()), 0);
  }
  ids.assign(f.n_node_sets, 0);
  if (f.n_node_sets) {
    EXPECT_GE(ex_get_ids(exo, EX_NODE_SET, ids.data()), 0);
  }
  for (int id : ids) {
    int n = 0, df = 0;
    EXPECT_GE(ex_get_set_param(exo, EX_NODE_SET, id, &n, &df), 0);
    f.node_sets[id].resize(n);
    EXPECT_GE(ex_get_set(exo, EX_NODE_SET, id, f.node_sets[id].data(), nullptr), 0);
  }
  ex_close(exo);
  return f;
}

/// Exodus side numbering (1-based, from the Exodus II manual).
std::vector<int> side_nodes(const std::vector<int>& elem, int side) {
  static const int kHex[6][4] = {{1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7},
                                 {1, 5, 8, 4}, {1, 4, 3, 2}, {5, 6, 7, 8}};
  static const std::vector<std::vector<int>> kWedge = {
      {1, 2, 5, 4}, {2, 3, 6, 5}, {1, 4, 6, 3}, {1, 3, 2}, {4, 5, 6}};
  std::vector<int> r;
  if (elem.size() == 8) {
    for (int k : kHex[side - 1]) r.push_back(elem[k - 1] - 1);
  } else {
    for (int k : kWedge[static_cast<size_t>(side - 1)]) r.push_back(elem[k - 1] - 1);
  }
  return r;
}

/// Equal up to a cyclic rotation (same orientation).
bool same_cycle(std::vector<int> a, const std::vector<int>& b) {
  if (a.size() != b.size()) return false;
  for (size_t r = 0; r < a.size(); ++r) {
    if (a == b) return true;
    std::rotate(a.begin(), a.begin() + 1, a.end());
  }
  return false;
}

void check_common(const TestMesh& t, const ExoFile& f) {
  ASSERT_EQ(f.dim, 3);
  ASSERT_EQ(f.nodes, static_cast<int>(t.db.node_count()));
  for (int i = 0; i < f.nodes; ++i) {
    EXPECT_EQ(f.x[i], t.db.node(i).x());
    EXPECT_EQ(f.y[i], t.db.node(i).y());
    EXPECT_EQ(f.z[i], t.db.node(i).z());
  }
  // One node set per surface: its nodes, 1-based ascending.
  ASSERT_EQ(f.node_sets.size(), t.db.surfaces().size());
  for (const auto& [sid, s] : t.db.surfaces()) {
    std::vector<int> expect;
    for (const auto& q : s.quads)
      for (int v : q) expect.push_back(v + 1);
    for (const auto& q : s.tris)
      for (int v : q) expect.push_back(v + 1);
    std::sort(expect.begin(), expect.end());
    expect.erase(std::unique(expect.begin(), expect.end()), expect.end());
    EXPECT_EQ(f.node_sets.at(sid), expect) << "node set " << sid;
  }
}

/// Every side set entry gives, through the Exodus side table, exactly the
/// surface's elements (same nodes, same orientation), from its first volume.
void check_side_sets(const TestMesh& t, const ExoFile& f) {
  ASSERT_EQ(f.side_sets.size(), t.db.surfaces().size());
  for (const auto& [sid, s] : t.db.surfaces()) {
    ASSERT_TRUE(f.side_sets.count(sid)) << "side set " << sid;
    const auto& [elems, sides] = f.side_sets.at(sid);
    ASSERT_EQ(elems.size(), s.size());
    std::vector<std::vector<int>> expect;
    for (const auto& q : s.quads) expect.emplace_back(q.begin(), q.end());
    for (const auto& q : s.tris) expect.emplace_back(q.begin(), q.end());
    for (size_t i = 0; i < elems.size(); ++i) {
      ASSERT_GE(elems[i], 1);
      ASSERT_LE(elems[i], f.elems);
      const auto nodes = side_nodes(f.elements[static_cast<size_t>(elems[i] - 1)], sides[i]);
      EXPECT_TRUE(same_cycle(nodes, expect[i])) << "surface " << sid << " element " << i;
    }
  }
}

TEST(ExodusWriter, OneBlock) {
  const TestMesh t = one_block();
  const std::string path = scratch_dir() + "/one.exo";
  io::write_exodus(path, t.db, t.model);
  const ExoFile f = read_exodus(path);
  check_common(t, f);
  EXPECT_EQ(f.elems, 8);
  ASSERT_EQ(f.block_ids, std::vector<int>{1});
  EXPECT_EQ(f.blocks.at(1).type, "HEX8");
  EXPECT_EQ(f.blocks.at(1).name, "block_one");
  EXPECT_EQ(f.blocks.at(1).count, 8);
  EXPECT_EQ(f.n_side_sets, 6);
  check_side_sets(t, f);
  EXPECT_FALSE(file_exists(path + ".tmp-" + std::to_string(getpid())));
}

TEST(ExodusWriter, TwoBlocksSharedSurfaceUsesFirstVolume) {
  const TestMesh t = two_blocks();
  const std::string path = scratch_dir() + "/two.e";
  io::write_exodus(path, t.db, t.model);
  const ExoFile f = read_exodus(path);
  check_common(t, f);
  EXPECT_EQ(f.elems, 16);
  ASSERT_EQ(f.block_ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(f.blocks.at(1).name, "left");
  EXPECT_EQ(f.blocks.at(2).name, "right");
  // The connectivity round-trips (1-based).
  const auto& h = t.db.volume(2).hexes;
  for (size_t e = 0; e < h.size(); ++e)
    for (size_t k = 0; k < 8; ++k) EXPECT_EQ(f.blocks.at(2).conn[e * 8 + k], h[e][k] + 1);
  check_side_sets(t, f);
  // The shared surface (bounding volumes 1 and 2) refers to volume 1's hexes.
  for (const auto& s : t.model.surfaces()) {
    if (s.volumes.size() != 2) continue;
    for (int e : f.side_sets.at(s.id).first) EXPECT_LE(e, 8) << "surface " << s.id;
  }
}

TEST(ExodusWriter, WedgesAndMixedBlocks) {
  {
    const TestMesh t = two_wedges();
    const std::string path = scratch_dir() + "/wedges.g";
    io::write_exodus(path, t.db, t.model);
    const ExoFile f = read_exodus(path);
    check_common(t, f);
    ASSERT_EQ(f.block_ids, std::vector<int>{1});
    EXPECT_EQ(f.blocks.at(1).type, "WEDGE");  // meshio reads WEDGE, not WEDGE6
    EXPECT_EQ(f.blocks.at(1).count, 2);
    check_side_sets(t, f);
  }
  const TestMesh t = mixed();
  const std::string path = scratch_dir() + "/mixed.exo";
  io::write_exodus(path, t.db, t.model);
  const ExoFile f = read_exodus(path);
  check_common(t, f);
  ASSERT_EQ(f.block_ids, (std::vector<int>{1, 1001}));
  EXPECT_EQ(f.blocks.at(1).type, "HEX8");
  EXPECT_EQ(f.blocks.at(1001).type, "WEDGE");
  EXPECT_EQ(f.blocks.at(1).name, "mixed");
  EXPECT_EQ(f.blocks.at(1001).name, "mixed_wedge");
  check_side_sets(t, f);
  // The wedge triangles are sides 4 (z = 0) and 5 (z = 1), two each.
  int tri_sides = 0;
  for (const auto& [id, s] : f.side_sets)
    for (size_t i = 0; i < s.first.size(); ++i)
      tri_sides += f.elements[static_cast<size_t>(s.first[i] - 1)].size() == 6 &&
                   (s.second[i] == 4 || s.second[i] == 5);
  EXPECT_EQ(tri_sides, 4);
}

TEST(ExodusWriter, SurfaceOnlyMeshWritesQuadBlocks) {
  const TestMesh t = surface_only();
  const std::string path = scratch_dir() + "/shell.exo";
  io::write_exodus(path, t.db, t.model);
  const ExoFile f = read_exodus(path);
  check_common(t, f);
  EXPECT_EQ(f.n_side_sets, 0);
  EXPECT_EQ(f.n_blocks, 6);
  EXPECT_EQ(f.elems, 24);
  for (const auto& [id, b] : f.blocks) {
    EXPECT_EQ(b.type, "QUAD4");
    EXPECT_EQ(b.name, "surface_" + std::to_string(id));
    const auto& q = t.db.surface(id).quads;
    ASSERT_EQ(b.count, static_cast<int>(q.size()));
    for (size_t e = 0; e < q.size(); ++e)
      for (size_t k = 0; k < 4; ++k) EXPECT_EQ(b.conn[e * 4 + k], q[e][k] + 1);
  }
}

}  // namespace
}  // namespace cooperage::test
