#include "framework/mesh2d/touching_loops.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace cooperage::mesh2d {
namespace {

using Eigen::Vector2d;

/// Groups of points (loop, index) closer than the tolerance, by a sort on
/// quantised coordinates (neighbouring cells checked too).
std::vector<std::vector<std::pair<int, int>>> coincident(
    const std::vector<std::vector<Vector2d>>& loops, double tolerance) {
  std::map<std::pair<long long, long long>, std::vector<std::pair<int, int>>> cells;
  const double cell = std::max(tolerance, 1e-300) * 4.0;
  for (size_t l = 0; l < loops.size(); ++l) {
    for (size_t k = 0; k < loops[l].size(); ++k) {
      const Vector2d& p = loops[l][k];
      cells[{static_cast<long long>(std::floor(p.x() / cell)),
             static_cast<long long>(std::floor(p.y() / cell))}]
          .emplace_back(static_cast<int>(l), static_cast<int>(k));
    }
  }
  std::map<std::pair<int, int>, std::pair<int, int>> parent;
  auto find = [&](std::pair<int, int> x) {
    while (parent.count(x) && parent[x] != x) x = parent[x];
    return x;
  };
  for (const auto& [key, members] : cells) {
    for (long long dx = -1; dx <= 1; ++dx) {
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find({key.first + dx, key.second + dy});
        if (it == cells.end()) continue;
        for (const auto& a : members) {
          for (const auto& b : it->second) {
            if (!(a < b)) continue;
            const Vector2d& pa = loops[static_cast<size_t>(a.first)][static_cast<size_t>(a.second)];
            const Vector2d& pb = loops[static_cast<size_t>(b.first)][static_cast<size_t>(b.second)];
            if ((pa - pb).norm() > tolerance) continue;
            const auto ra = find(a), rb = find(b);
            if (!parent.count(ra)) parent[ra] = ra;
            if (!parent.count(rb)) parent[rb] = rb;
            if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
          }
        }
      }
    }
  }
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> groups;
  for (const auto& [x, p] : parent) groups[find(x)].push_back(x);
  std::vector<std::vector<std::pair<int, int>>> out;
  for (auto& [root, members] : groups) {
    if (members.size() > 1) out.push_back(std::move(members));
  }
  return out;
}

}  // namespace

SeparatedLoops separate_touching_points(const std::vector<std::vector<Vector2d>>& loops,
                                        double tolerance, double fraction) {
  SeparatedLoops out;
  out.loops = loops;
  out.source.resize(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) {
    for (size_t k = 0; k < loops[l].size(); ++k)
      out.source[l].push_back({static_cast<int>(l), static_cast<int>(k)});
  }
  // Merge loops that share a point: b into a at the shared point, so the
  // merged loop walks a to the point, all of b, the point again, the rest
  // of a (the face stays on the left throughout).
  for (;;) {
    bool merged = false;
    for (const auto& group : coincident(out.loops, tolerance)) {
      for (size_t x = 1; x < group.size() && !merged; ++x) {
        const auto [la, ia] = group[0];
        const auto [lb, ib] = group[x];
        if (la == lb) continue;
        auto& A = out.loops[static_cast<size_t>(la)];
        auto& B = out.loops[static_cast<size_t>(lb)];
        auto& SA = out.source[static_cast<size_t>(la)];
        auto& SB = out.source[static_cast<size_t>(lb)];
        std::vector<Vector2d> loop(A.begin(), A.begin() + ia + 1);
        std::vector<LoopPointRef> src(SA.begin(), SA.begin() + ia + 1);
        for (size_t s = 1; s <= B.size(); ++s) {
          const size_t k = (static_cast<size_t>(ib) + s) % B.size();
          loop.push_back(B[k]);
          src.push_back(SB[k]);
        }
        loop.insert(loop.end(), A.begin() + ia + 1, A.end());
        src.insert(src.end(), SA.begin() + ia + 1, SA.end());
        A = std::move(loop);
        SA = std::move(src);
        out.loops.erase(out.loops.begin() + lb);
        out.source.erase(out.source.begin() + lb);
        merged = true;
      }
      if (merged) break;
    }
    if (!merged) break;
  }
  // Every copy moves into its own corner, along the bisector of the wedge
  // swept counter-clockwise from the outgoing to the incoming edge (the
  // face lies on the left of every loop).
  const auto groups = coincident(out.loops, tolerance);
  std::vector<std::vector<Vector2d>> moved = out.loops;
  for (const auto& group : groups) {
    for (const auto& [l, k] : group) {
      const auto& loop = out.loops[static_cast<size_t>(l)];
      const size_t n = loop.size();
      const Vector2d& x = loop[static_cast<size_t>(k)];
      const Vector2d& p = loop[(static_cast<size_t>(k) + n - 1) % n];
      const Vector2d& q = loop[(static_cast<size_t>(k) + 1) % n];
      const double a_next = std::atan2(q.y() - x.y(), q.x() - x.x());
      const double a_prev = std::atan2(p.y() - x.y(), p.x() - x.x());
      double sweep = a_prev - a_next;
      while (sweep <= 0) sweep += 2.0 * M_PI;
      while (sweep > 2.0 * M_PI) sweep -= 2.0 * M_PI;
      const double a = a_next + 0.5 * sweep;
      const double step = fraction * std::min((p - x).norm(), (q - x).norm());
      moved[static_cast<size_t>(l)][static_cast<size_t>(k)] =
          x + step * Vector2d(std::cos(a), std::sin(a));
      ++out.moved;
    }
  }
  out.loops = std::move(moved);
  return out;
}

}  // namespace cooperage::mesh2d
