// Seeded randomized test of pave_2d: 200+ generated non-convex faces with
// random holes (even node count in total; single loops may be odd). Every face must mesh all-quad,
// without an inverted quad, with its boundary nodes untouched; a failure
// prints the seed and the face.
#include "pave_test_util.h"

#include "framework/core/error.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

namespace cooperage::pave::testing {
namespace {

TEST(Pave2DRandom, TwoHundredFacesMeshAllQuadWithoutInversion) {
  // COOPERAGE_PAVE_RANDOM_FACES=<n> runs a longer campaign;
  // COOPERAGE_PAVE_RANDOM_FIRST=<seed> starts it elsewhere (to rerun a seed).
  const char* first = std::getenv("COOPERAGE_PAVE_RANDOM_FIRST");
  const unsigned first_seed =
      first ? static_cast<unsigned>(std::strtoul(first, nullptr, 10)) : 1000u;
  const char* env = std::getenv("COOPERAGE_PAVE_RANDOM_FACES");
  const int faces = env ? std::max(1, std::atoi(env)) : 240;
  int failures = 0, holes = 0, below_03 = 0, odd_loops = 0;
  unsigned worst_seed = 0;
  double worst = 1, median_sum = 0;
  for (int f = 0; f < faces; ++f) {
    const unsigned seed = first_seed + static_cast<unsigned>(f);
    const Loops loops = random_face(seed);
    holes += static_cast<int>(loops.size()) - 1;
    for (const auto& l : loops) odd_loops += l.size() % 2;
    std::string problem;
    QuadMesh2D m;
    try {
      m = pave_2d(loops);
      problem = check_mesh(loops, m);
    } catch (const MeshingError& e) {
      problem = std::string("threw: ") + e.what();
    }
    if (!problem.empty()) {
      ++failures;
      ADD_FAILURE() << "seed " << seed << ": " << problem << "\nface:\n" << describe(loops);
      continue;
    }
    const Stats s = stats(m);
    if (s.min_sj < worst) worst_seed = seed;
    worst = std::min(worst, s.min_sj);
    below_03 += s.min_sj < 0.3;
    median_sum += s.median_sj;
  }
  std::printf(
      "random faces: %d faces, %d holes, %d odd loops, %d failures; worst min scaled Jacobian %.3f "
      "(seed %u), "
      "%d faces with min < 0.3; mean median %.3f\n",
      faces, holes, odd_loops, failures, worst, worst_seed, below_03,
      median_sum / std::max(1, faces - failures));
  EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace cooperage::pave::testing
