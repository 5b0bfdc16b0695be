// The seam of a cap the sweep meshes (a target band on a sphere, cone or
// cylinder, periodic in CAD) is no boundary for the sweep (loop_nodes drops
// it), so the stacks project their own nodes across it; the seam curve's
// nodes, meshed before, must be those nodes, or they would be left unused
// beside them. The source cap's seam projects onto the target's seam (the
// plan gives both seams as many intervals): the image of its k-th node
// becomes the target seam's k-th node, before the layers are swept (so the
// sweep's own quality check sees it).
#include "schemes/cooper/loop_nodes.h"
#include "schemes/cooper/sweep_state.h"

#include <algorithm>

namespace cooperage::cooper::detail {

void weld_seam_images(SweepState& s, size_t b, const NodeImage& below) {
  for (const auto& [u, l] : s.barrels[b].matches) {
    const Piece& pu = s.pieces[static_cast<size_t>(u)];
    const Piece& pl = s.pieces[static_cast<size_t>(l)];
    if (!pu.cap || !pl.cap || pl.premeshed) continue;
    const int ts = single_seam(s.model.surface(pl.cap));
    if (!ts) continue;
    const int us = single_seam(s.model.surface(pu.cap));
    std::vector<int> up = us ? s.db.curve_nodes(us) : std::vector<int>{};
    std::vector<int> down = s.db.curve_nodes(ts);
    if (up.size() != down.size()) {
      fail(s.vid, "the seam of surface " + std::to_string(pl.cap) +
                      " has no seam of as many intervals on its source surface " +
                      std::to_string(pu.cap) + " to take its nodes from");
    }
    // Orient the target's seam as the source's: its first node under the
    // source seam's first node (both ends are rim nodes, paired by ribs).
    auto image = [&](int g) -> int {
      const auto lit = s.local.find(g);
      if (lit == s.local.end()) return -1;
      const auto bit = below.find(lit->second);
      return bit == below.end() ? -1 : bit->second;
    };
    auto local_of = [&](int g) {
      const auto it = s.local.find(g);
      return it == s.local.end() ? -2 : it->second;
    };
    if (image(up.front()) == local_of(down.back()) && image(up.back()) == local_of(down.front()))
      std::reverse(down.begin(), down.end());
    if (image(up.front()) != local_of(down.front()) || image(up.back()) != local_of(down.back())) {
      fail(s.vid, "the seams of surfaces " + std::to_string(pu.cap) + " and " +
                      std::to_string(pl.cap) + " do not end on the same ribs");
    }
    for (size_t k = 1; k + 1 < up.size(); ++k) {
      const int lower = image(up[k]);
      const int g = down[k];
      if (lower < 0 || s.out.global[static_cast<size_t>(lower)] >= 0 || s.local.count(g)) {
        fail(s.vid, "node " + std::to_string(k) + " of the seam of surface " +
                        std::to_string(pl.cap) + " has no swept node to take");
      }
      s.out.global[static_cast<size_t>(lower)] = g;
      s.out.coords[static_cast<size_t>(lower)] = s.db.node(g);
      if (!s.out.owners.empty()) s.out.owners[static_cast<size_t>(lower)] = mesh::NodeOwner{};
      s.local[g] = lower;
    }
  }
}

void check_seams_welded(SweepState& s) {
  for (const Piece& p : s.pieces) {
    if (!p.alive || !p.cap || p.premeshed) continue;
    const int seam = single_seam(s.model.surface(p.cap));
    if (!seam) continue;
    const std::vector<int>& chain = s.db.curve_nodes(seam);
    for (size_t k = 1; k + 1 < chain.size(); ++k) {
      if (!s.local.count(chain[k])) {
        fail(s.vid, "the mesh swept onto surface " + std::to_string(p.cap) +
                        " leaves the nodes of its seam, curve " + std::to_string(seam) +
                        ", unused (its source has no seam that projects onto it)");
      }
    }
  }
}

}  // namespace cooperage::cooper::detail
