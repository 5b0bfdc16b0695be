// part_ids.h: the pieces of a cut named by the part's entities. Checked by
// what a cut conserves: the pieces' faces on a face of the part add up to
// its area, their curves on a curve of the part to its length; whatever
// lies on no entity of the part lies on the cut.
#include "framework/decompose/part_ids.h"

#include "framework/geometry/occ/solid_pieces.h"
#include "framework/geometry/occ/workbench.h"

#include <gtest/gtest.h>

#include <map>

namespace cooperage::decompose {
namespace {

// Volume 2 of the part: a block with a through hole, beside a brick
// (volume 1), so the pieces' ids and the part's differ.
struct Cut {
  geom::Model part;
  geom::Model pieces;  // volume 2 cut at x = 2, through the hole's axis
};

Cut block_with_hole_cut_through_its_axis() {
  occ::Workbench bench;
  bench.brick("a", {-2, 0, 0}, {2, 3, 2});
  bench.brick("block", {0, 0, 0}, {4, 3, 2});
  bench.cylinder("hole", {2, 1.5, -1}, {0, 0, 1}, 0.6, 4);
  bench.cut("b", {"block", "hole"});
  Cut out;
  out.part = bench.build_model();
  const occ::SolidPieces all = occ::SolidPieces::of(bench);
  out.pieces =
      all.split(1, {occ::CutSurface::Kind::Plane, {2, 0, 0}, {1, 0, 0}, 0}).build_model(false);
  return out;
}

bool on_cut(const geom::Vec3& p) { return std::abs(p.x() - 2) < 1e-9; }

TEST(PartIds, ThePiecesFacesOnAFaceOfThePartCoverItAndTheRestIsTheCut) {
  const Cut c = block_with_hole_cut_through_its_axis();
  ASSERT_EQ(c.part.volumes().size(), 2u);
  ASSERT_EQ(c.pieces.volumes().size(), 2u);
  const PartIds ids(c.part, 2);
  std::map<int, double> area;  // part surface -> area of the piece faces on it
  int cut_faces = 0;
  for (const geom::Surface& s : c.pieces.surfaces()) {
    const int mine = ids.surface(c.pieces, s.id);
    if (mine == 0) {
      ++cut_faces;
      EXPECT_EQ(s.volumes.size(), 2u) << "surface " << s.id << " lies on no face of the part";
      EXPECT_TRUE(on_cut(s.box.min) && on_cut(s.box.max)) << "surface " << s.id;
      continue;
    }
    EXPECT_EQ(c.part.surface(mine).geometry->type(), s.geometry->type());
    area[mine] += s.area;
  }
  EXPECT_EQ(cut_faces, 2);  // on either side of the hole
  for (int s : c.part.surfaces_of(2))
    EXPECT_NEAR(area[s], c.part.surface(s).area, 1e-6 * c.part.surface(s).area) << "surface " << s;
}

TEST(PartIds, ThePiecesCurvesOnACurveOfThePartAddUpToItAndTheRestLieOnTheCut) {
  const Cut c = block_with_hole_cut_through_its_axis();
  const PartIds ids(c.part, 2);
  std::map<int, double> length;
  for (const geom::Curve& k : c.pieces.curves()) {
    const int mine = ids.curve(c.pieces, k.id);
    if (mine == 0) {
      const auto [a, b] = k.geometry->range();
      EXPECT_TRUE(on_cut(k.geometry->point(a)) && on_cut(k.geometry->point(0.5 * (a + b))))
          << "curve " << k.id << " lies on no curve of the part, nor on the cut";
      continue;
    }
    length[mine] += k.length;
  }
  for (const auto& [mine, sum] : length)
    EXPECT_NEAR(sum, c.part.curve(mine).length, 1e-6 * sum) << "curve " << mine;
  // Every curve of the block's outer faces is covered (the hole's circles
  // and its seam, if the kernel keeps one, may lie on the cut).
  for (int s : c.part.surfaces_of(2)) {
    if (c.part.surface(s).geometry->type() != geom::SurfaceType::Plane) continue;
    for (const auto& loop : c.part.surface(s).loops)
      for (const auto& use : loop.uses) EXPECT_GT(length[use.curve], 0.0) << "curve " << use.curve;
  }
}

TEST(PartIds, ThePiecesVerticesAreThePartsOrOnTheCut) {
  const Cut c = block_with_hole_cut_through_its_axis();
  const PartIds ids(c.part, 2);
  int on_part = 0;
  for (const geom::Vertex& v : c.pieces.vertices()) {
    const int mine = ids.vertex(c.pieces, v.id);
    if (mine == 0) {
      EXPECT_TRUE(on_cut(v.point)) << "vertex " << v.id;
      continue;
    }
    ++on_part;
    EXPECT_LT((c.part.vertex(mine).point - v.point).norm(), 1e-9);
  }
  EXPECT_GE(on_part, 8);  // the block's corners at least
}

TEST(PartIds, TextNamesThePartsEntitiesTheCutAndThePieces) {
  const Cut c = block_with_hole_cut_through_its_axis();
  const PartIds ids(c.part, 2);
  int face = 0, cut = 0, edge = 0, corner = 0;
  for (const geom::Surface& s : c.pieces.surfaces()) {
    if (s.volumes.size() > 1 && !cut) cut = s.id;
    if (s.volumes.size() == 1 && !face) face = s.id;
  }
  for (const geom::Curve& k : c.pieces.curves())
    if (!edge && ids.curve(c.pieces, k.id)) edge = k.id;
  for (const geom::Vertex& v : c.pieces.vertices())
    if (!corner && ids.vertex(c.pieces, v.id)) corner = v.id;
  ASSERT_TRUE(face && cut && edge && corner);
  const std::string f = std::to_string(face), k = std::to_string(cut);
  const std::string part_face = std::to_string(ids.surface(c.pieces, face));
  const std::string part_edge = std::to_string(ids.curve(c.pieces, edge));
  const std::string part_corner = std::to_string(ids.vertex(c.pieces, corner));

  EXPECT_EQ(ids.translate("cooper: volume 1: surface " + f + " cannot be a side", c.pieces, 1),
            "cooper: the piece: surface " + part_face + " cannot be a side");
  EXPECT_EQ(ids.translate("surface " + k + ": no", c.pieces), "the cut face: no");
  EXPECT_EQ(ids.translate("sides " + f + ", " + k + " and " + f + ", ...", c.pieces),
            "sides " + part_face + ", the cut face and " + part_face + ", ...");
  EXPECT_EQ(ids.translate("along curve " + std::to_string(edge) + " at vertex " +
                              std::to_string(corner) + ")",
                          c.pieces),
            "along curve " + part_edge + " at vertex " + part_corner + ")");
  EXPECT_EQ(ids.translate("volume 2 and volume 1", c.pieces, 1), "piece 2 and the piece");
  // Not ids of the pieces: counts, decimals, other words, unknown ids.
  for (const std::string same :
       {"volume map needs 6 mappable surfaces, volume has 15", "surface 3.5", "subsurface 3",
        "surface 999", "surface 3rd", "hex 14 of layer 0"})
    EXPECT_EQ(ids.translate(same, c.pieces), same);
}

}  // namespace
}  // namespace cooperage::decompose
