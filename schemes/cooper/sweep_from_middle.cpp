// Barrels meshed from the middle (Blacker 1996, sec. 6.1: a cap stack is
// meshed once and its mesh projected to every cap of the stack): when the
// subcaps arriving on the two ends of a barrel overlap (sec. 5.3), their
// pieces are meshed in that barrel (sweep_two_sided.cpp) and each arriving
// barrel is then swept from its virtual cap out to its real cap.
#include "schemes/cooper/many_to_one_builder.h"
#include "schemes/cooper/sweep_barrel.h"

#include <utility>

namespace cooperage::cooper::detail {

// cite: Blacker 1996, sec. 6.1 (a stack's mesh, made in the middle, is
// projected to every cap of the stack) and 6.2-6.3.
BarrelReport Builder::sweep_out(size_t b, bool flip) {
  const BarrelPlan& p = plan_.barrels[b];
  const std::string name = "barrel " + std::to_string(b + 1) + " out to cap " + std::to_string(p.upper);
  BarrelInput bin;
  std::vector<int> lower_nodes;
  const Barrel barrel = ribs(b, bin, lower_nodes);  // from the real cap to the middle
  const VirtualCap& cap = virtual_[b];
  if (cap.quads.empty() && cap.tris.empty()) fail(vid_, name + ": its virtual cap was not meshed");
  const size_t B = barrel.ribs.size();
  const size_t J = static_cast<size_t>(barrel.layers);
  SweepInput in;
  in.layers = static_cast<int>(J);
  in.boundary = static_cast<int>(B);
  std::vector<int> cap_entity;
  std::unordered_map<int, int> cap_index;
  auto index_of = [&](int n) {
    auto [it, added] = cap_index.emplace(n, static_cast<int>(cap_entity.size()));
    if (added) cap_entity.push_back(n);
    return it->second;
  };
  size_t r = 0;
  for (const auto& loop : bin.upper_loops) {
    in.loop_starts.push_back(r);
    for (size_t k = 0; k < loop.size(); ++k, ++r) index_of(existing(barrel.ribs[r].back()));
  }
  for (const mesh::Quad& face : cap.quads) {
    const mesh::Quad q = flip ? reversed(face) : face;
    in.quads.push_back({index_of(q[0]), index_of(q[1]), index_of(q[2]), index_of(q[3])});
  }
  for (const mesh::Tri& face : cap.tris) {
    const mesh::Tri t = flip ? reversed(face) : face;
    in.tris.push_back({index_of(t[0]), index_of(t[1]), index_of(t[2])});
  }
  in.cap_nodes = static_cast<int>(cap_entity.size());
  for (int n : cap_entity) in.source.push_back(out_.coords[static_cast<size_t>(n)]);
  for (const auto& rib : barrel.ribs) {
    for (size_t j = 0; j <= J; ++j) in.ribs.push_back(db_.node(rib[J - j]));
  }
  const auto geometry = model_.surface(p.upper).geometry;
  in.project_target = [geometry](const Vec3& x) { return geometry->project(x).point; };
  const SweepResult sweep = sweep_barrel(in);
  if (!sweep.ok) fail(vid_, name + ": " + sweep.why);
  const size_t n = cap_entity.size();
  std::vector<int> node(sweep.points.size());
  for (size_t j = 0; j <= J; ++j) {
    for (size_t i = 0; i < n; ++i) {
      const size_t q = j * n + i;
      if (i < B) {
        node[q] = existing(barrel.ribs[i][J - j]);
      } else if (j == 0) {
        node[q] = cap_entity[i];
      } else if (j == J) {
        node[q] = out_.add_owned(sweep.points[q], {2, p.upper});
      } else {
        node[q] = out_.add(sweep.points[q]);
      }
    }
  }
  for (const auto& h : sweep.hexes) out_.hexes.push_back(renumbered(h, node));
  for (const auto& w : sweep.wedges) out_.wedges.push_back(renumbered(w, node));
  const bool outward = model_.sense_in(p.upper, vid_) == geom::Sense::Forward;
  const size_t top = J * n;
  auto on_top = [&](auto f) {
    for (auto& c : f) c = node[top + static_cast<size_t>(c)];
    return outward ? f : reversed(f);
  };
  for (const auto& q : in.quads) out_.surface_quads[p.upper].push_back(on_top(q));
  for (const auto& t : in.tris) out_.surface_tris[p.upper].push_back(on_top(t));
  return {p.upper, barrel.layers, sweep.min_scaled_jacobian, sweep.smoothed, {}};
}

}  // namespace cooperage::cooper::detail
