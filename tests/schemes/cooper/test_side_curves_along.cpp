// The two curves along a sweep's side are spaced alike (side_lattice.h,
// side_along_pairs; cooper_scheme.cpp drops both size functions when they
// differ). The sweep links node k of one ring to node k of the next; a
// curve graded by a feature near it on one cap only (a thin strip) sheared
// the ribs by elements, and imprinting or the blend then failed.
#include "support/hex_mesh_check.h"

#include "framework/core/error.h"
#include "framework/geometry/occ/workbench.h"
#include "framework/pipeline/mesher.h"
#include "schemes/builtin_schemes.h"
#include "selector/select_schemes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace cooperage::cooper {
namespace {

// The piece of pyocc_face_recognition that failed (tests/schemes/cooper/
// data/cooper_strip_over_overhang.xml): a 153 x 5 strip (y -25..-20) over
// a 74.551 x 80 overhang below it with one rounded corner (radius 5), cut at
// z = 185. The upper piece sweeps along z from its two bottom faces (the
// strip's cut face and the overhang's underside) to its top. The strip is 5
// thick, so the sizing grades its edges to 5 wherever the strip is a face of
// its own: all along the bottom edge y = -20, only over x < 78.45 on top.
geom::Model strip_over_overhang() {
  occ::Workbench wb;
  wb.brick("strip", {0, -25, 0}, {153, 5, 225});
  wb.brick("o1", {83.449, -105, 185}, {69.551, 80, 40});
  wb.brick("o2", {78.449, -100, 185}, {5, 75, 40});
  wb.cylinder("c", {83.449, -100, 185}, {0, 0, 1}, 5, 40);
  wb.fuse("part", {"strip", "o1", "o2", "c"});
  wb.webcut("part", {0, 0, 185}, {0, 0, 1});
  return wb.build_model();
}

// x of the mesh nodes on the line y = -20, z = z0 (the strip's wall).
std::vector<double> wall_nodes(const mesh::MeshDB& db, double z0) {
  std::vector<double> x;
  for (size_t i = 0; i < db.node_count(); ++i) {
    const geom::Vec3& p = db.node(static_cast<int>(i));
    if (std::abs(p.y() + 20) < 1e-6 && std::abs(p.z() - z0) < 1e-6) x.push_back(p.x());
  }
  std::sort(x.begin(), x.end());
  return x;
}

// The model meshed with the built-in schemes on one thread; a failure is
// a test failure naming the size.
std::optional<pipeline::MeshResult> mesh_at(const geom::Model& model,
                                            const io::MeshSettings& settings) {
  scheme::Registry registry;
  register_builtin_schemes(registry);
  pipeline::MeshOptions options = selector::mesh_options();
  options.threads = 1;
  try {
    return pipeline::mesh_model(model, settings, registry, options);
  } catch (const MeshingError& e) {
    ADD_FAILURE() << "size " << *settings.size << ": " << e.what();
    return std::nullopt;
  }
}

// On main these failed from size 8 up ("subcap imprinting failed", or "hex
// N of layer 4 is inverted"); every size meshes now, the wall's nodes lie
// straight above each other, and the hexes fill the volume.
TEST(CooperSideCurvesAlong, StripOverOverhangMeshesAtEverySize) {
  const geom::Model model = strip_over_overhang();
  ASSERT_EQ(model.volumes().size(), 2u);
  const double r = 5;
  const double exact = 153.0 * 5 * 225 + (74.551 * 80 - (r * r - M_PI * r * r / 4)) * 40;
  for (double size : {7.0, 8.0, 9.0, 10.0, 12.0, 15.0}) {
    io::MeshSettings settings;
    settings.size = size;
    const std::optional<pipeline::MeshResult> meshed = mesh_at(model, settings);
    if (!meshed) continue;
    const pipeline::MeshResult& res = *meshed;
    EXPECT_EQ(res.plan.volumes.at(2).scheme, "cooper") << size;
    const testing::HexMeshSummary s = testing::check_hex_mesh(model, res.mesh);
    EXPECT_NEAR(s.volume, exact, 0.005 * exact) << size;
    EXPECT_GE(s.min_sj, 0.3) << size;
    const std::vector<double> bottom = wall_nodes(res.mesh, 185);
    const std::vector<double> top = wall_nodes(res.mesh, 225);
    ASSERT_EQ(bottom.size(), top.size()) << size;
    double shear = 0;
    for (size_t k = 0; k < top.size(); ++k) shear = std::max(shear, std::abs(top[k] - bottom[k]));
    EXPECT_LT(shear, 1e-6 * size) << size;
    std::printf("[cooper sides] strip over overhang, size %g: %zu hexes, min SJ %.4f\n", size,
                s.hexes, s.min_sj);
  }
}

// Campaign seed 20 case 85: a lug (radius 4.92) on a block's side, 0.04
// proud of the block's next side. Its bottom face meets that side at a
// 7.3-degree corner, so its arc is graded from there; the lug's top arc is
// not (the top face is the block's), and the pair was made uniform. The
// bottom arc's first chord then crossed the face's own edge ("pave: the
// boundary is not a valid region ... touches or crosses itself") at every
// size. Both arcs now take the bottom's grading, facing node for node.
TEST(CooperSideCurvesAlong, ARingGradedToASliverCornerLendsItsPartnerItsProfile) {
  occ::Workbench wb;
  wb.brick("block", {0, 0, 0}, {62.99, 25.52, 32.12});
  wb.cylinder("lug", {62.99, 20.64, 10.03}, {0, 0, 1}, 4.92, 22.09);
  wb.fuse("part", {"block", "lug"});
  const geom::Model model = wb.build_model();
  ASSERT_EQ(model.volumes().size(), 1u);
  const double exact = model.volumes().front().volume;
  for (double size : {8.535, 6.0, 4.0, 3.0}) {
    io::MeshSettings settings;
    settings.size = size;
    settings.decompose = io::Decompose::Off;
    settings.finer_retries = 0;
    const std::optional<pipeline::MeshResult> meshed = mesh_at(model, settings);
    if (!meshed) continue;
    const pipeline::MeshResult& res = *meshed;
    const testing::HexMeshSummary s = testing::check_hex_mesh(model, res.mesh);
    EXPECT_NEAR(s.volume, exact, 0.01 * exact) << size;
    EXPECT_GT(s.min_sj, 0.0) << size;
    // The nodes on the lug's round face at its bottom and top, by angle.
    auto ring = [&](double z0) {
      std::vector<double> angles;
      for (size_t i = 0; i < res.mesh.node_count(); ++i) {
        const geom::Vec3& p = res.mesh.node(static_cast<int>(i));
        const double r = std::hypot(p.x() - 62.99, p.y() - 20.64);
        if (std::abs(p.z() - z0) < 1e-6 && std::abs(r - 4.92) < 1e-6 && p.x() > 62.99 + 1e-6)
          angles.push_back(std::atan2(p.y() - 20.64, p.x() - 62.99));
      }
      std::sort(angles.begin(), angles.end());
      return angles;
    };
    const std::vector<double> bottom = ring(10.03), top = ring(32.12);
    ASSERT_EQ(bottom.size(), top.size()) << size;
    ASSERT_GE(bottom.size(), 2u) << size;
    for (size_t k = 0; k < top.size(); ++k) EXPECT_NEAR(top[k], bottom[k], 1e-6) << size;
    std::printf("[cooper sides] lug 0.04 proud, size %g: %zu hexes, min SJ %.4f\n", size, s.hexes,
                s.min_sj);
  }
}

}  // namespace
}  // namespace cooperage::cooper
