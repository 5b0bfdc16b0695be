#include "schemes/cooper/wall_walk.h"

#include <cmath>

namespace cooperage::cooper {

std::vector<WallStep> wall_walk(const FaceFact& face, const SideLattice& lattice) {
  if (face.loops.size() != 1) return {};
  const auto& loop = face.loops.front();
  if (face.angles.size() != loop.size()) return {};
  size_t first = loop.size();
  for (size_t k = 0; k < loop.size() && first == loop.size(); ++k) {
    if (lattice.along.count(loop[k].curve)) first = k;
  }
  if (first == loop.size()) return {};
  std::vector<WallStep> out;
  int dir = 0;
  for (size_t m = 0; m < loop.size(); ++m) {
    const size_t k = (first + m) % loop.size();
    if (m > 0) {
      const long turn = std::lround((180.0 - face.angles[k]) / 90.0);
      dir = static_cast<int>(((dir + turn) % 4 + 4) % 4);
    }
    const bool along = lattice.along.count(loop[k].curve) > 0;
    if (along != (dir % 2 == 0)) return {};
    out.push_back({k, dir, along});
  }
  return out;
}

bool upright_wall(const VolumeFacts& facts, const FaceFact& face, const SideLattice& lattice,
                  const geom::Vec3& d, double tol) {
  for (const auto& loop : face.loops) {
    for (const UseFact& u : loop) {
      if (lattice.along.count(u.curve)) continue;
      const CurveFact& c = facts.curves.at(u.curve);
      const geom::Vec3 foot = facts.vertices.at(c.start);
      for (const geom::Vec3& y : c.samples) {
        const geom::Vec3 e = y - foot;
        if ((e - e.dot(d) * d).norm() > tol) return false;
      }
    }
  }
  return true;
}

}  // namespace cooperage::cooper
