// SideParity (side_parity.h) is a necessary test of a sorting: it may only
// refuse sortings that side_lattice() refuses. Checked over every subset of
// the faces of hand-made polyhedra, with what it must refuse and keep
// following from the lattice of a brick.
#include "polyhedron_facts.h"

#include "schemes/cooper/side_lattice.h"
#include "schemes/cooper/side_parity.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace cooperage::cooper {
namespace side_parity_test {

using facts_test::cube;
using facts_test::oriented;
using facts_test::pocket;
using facts_test::PolyFace;
using geom::Vec3;

const Vec3 kUp(0, 0, 1), kDown(0, 0, -1);

// An L-shaped plate 1 thick: its top and bottom have a 270-degree corner.
std::vector<PolyFace> l_plate() {
  const std::vector<Vec3> l = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  std::vector<PolyFace> f;
  for (size_t k = 0; k < l.size(); ++k) {
    const Vec3 a = l[k], b = l[(k + 1) % l.size()];
    const Vec3 out = (b - a).cross(kUp).normalized();
    f.push_back({oriented({a, b, b + kUp, a + kUp}, out)});
  }
  std::vector<Vec3> top;
  for (const Vec3& p : l) top.push_back(p + kUp);
  f.push_back({oriented(l, kDown)});
  f.push_back({oriented(top, kUp)});
  return f;
}

// Every subset of the faces: the ones the parity refuses, after checking
// that the lattice refuses each of them too.
int refused_by_parity_only_when_the_lattice_refuses(const std::vector<PolyFace>& faces,
                                                    int* lattices) {
  const VolumeFacts facts = facts_test::polyhedron_facts(faces);
  const SideParity parity(facts);
  const int n = static_cast<int>(facts.faces.size());
  int refused = 0;
  *lattices = 0;
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::set<int> caps;
    for (int k = 0; k < n; ++k) {
      if (mask & (1 << k)) caps.insert(facts.faces[static_cast<size_t>(k)].id);
    }
    const bool lattice = side_lattice(facts, caps).ok;
    const bool agree = parity.can_agree(caps);
    *lattices += lattice ? 1 : 0;
    if (lattice) {
      EXPECT_TRUE(agree) << "caps mask " << mask;
    }
    refused += agree ? 0 : 1;
  }
  return refused;
}

TEST(SideParity, RefusesOnlySortingsTheLatticeRefuses) {
  for (const auto& [name, faces] : std::vector<std::pair<std::string, std::vector<PolyFace>>>{
           {"cube", cube()}, {"pocket", pocket()}, {"L plate", l_plate()}}) {
    SCOPED_TRACE(name);
    int lattices = 0;
    const int refused = refused_by_parity_only_when_the_lattice_refuses(faces, &lattices);
    const int subsets = (1 << static_cast<int>(faces.size())) - 1;
    // Some sortings have a lattice, and the parity alone refuses most of
    // those that do not (the test would pass with a parity that refuses
    // nothing, so say how much it does).
    EXPECT_GT(lattices, 0);
    EXPECT_GT(refused, (subsets - lattices) / 2) << refused << " of " << subsets - lattices;
  }
}

TEST(SideParity, ABricksOppositeFacesAreCapsAndOneFaceAloneIsNot) {
  const VolumeFacts facts = facts_test::polyhedron_facts(cube());
  const SideParity parity(facts);
  // Top alone: the walls carry "along" down to the bottom's four edges,
  // but the bottom square's edges alternate roles as a side.
  EXPECT_FALSE(parity.can_agree({6}));
  EXPECT_FALSE(side_lattice(facts, {6}).ok);
  EXPECT_TRUE(parity.can_agree({5, 6}));
  EXPECT_TRUE(parity.can_agree({1, 3}));
  // A wall and the bottom: the wall x = 1 meets both caps, and its bottom
  // edge and the vertical edge beside it cannot both run along.
  EXPECT_FALSE(parity.can_agree({5, 1}));
  EXPECT_FALSE(side_lattice(facts, {5, 1}).ok);
}

}  // namespace side_parity_test
}  // namespace cooperage::cooper
