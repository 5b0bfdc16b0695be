#include "schemes/quad_dominant/pave_with_ear.h"

#include "framework/mesh2d/parity_ear.h"

namespace cooperage::quad_dominant {

PavedWithEar pave_with_ear(const std::vector<std::vector<Eigen::Vector2d>>& loops) {
  size_t total = 0;
  for (const auto& l : loops) total += l.size();
  const auto ear = total % 2 != 0 ? mesh2d::parity_ear(loops) : std::nullopt;
  if (!ear) return {pave::pave_2d(loops), std::nullopt};

  // The rest: every loop as given but the ear's corner; the input index of
  // each of its boundary nodes; the triangle in input indices.
  std::vector<std::vector<Eigen::Vector2d>> rest;
  std::vector<int> input_of;
  std::array<int, 3> tri{};
  int first = 0;
  for (size_t l = 0; l < loops.size(); ++l) {
    const int n = static_cast<int>(loops[l].size());
    rest.emplace_back();
    for (int i = 0; i < n; ++i) {
      if (l == ear->loop && i == static_cast<int>(ear->index)) continue;
      rest.back().push_back(loops[l][static_cast<size_t>(i)]);
      input_of.push_back(first + i);
    }
    if (l == ear->loop) {
      const int i = static_cast<int>(ear->index);
      // prev -> corner -> next turns left at a convex corner: counter-clockwise.
      tri = {first + (i + n - 1) % n, first + i, first + (i + 1) % n};
    }
    first += n;
  }
  const pave::QuadMesh2D paved = pave::pave_2d(rest);
  const int rest_boundary = paved.boundary_count;
  const int boundary = static_cast<int>(total);
  const auto input_index = [&](int k) {
    return k < rest_boundary ? input_of[static_cast<size_t>(k)] : boundary + (k - rest_boundary);
  };
  PavedWithEar out;
  out.mesh.boundary_count = boundary;
  out.mesh.points.resize(paved.points.size() + 1);
  for (size_t l = 0, k = 0; l < loops.size(); ++l) {
    for (const Eigen::Vector2d& p : loops[l]) out.mesh.points[k++] = p;
  }
  for (int k = rest_boundary; k < static_cast<int>(paved.points.size()); ++k)
    out.mesh.points[static_cast<size_t>(input_index(k))] = paved.points[static_cast<size_t>(k)];
  for (const auto& q : paved.quads)
    out.mesh.quads.push_back(
        {input_index(q[0]), input_index(q[1]), input_index(q[2]), input_index(q[3])});
  out.ear = tri;
  return out;
}

}  // namespace cooperage::quad_dominant
