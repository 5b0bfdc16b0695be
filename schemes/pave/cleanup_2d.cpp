#include "schemes/pave/cleanup_2d.h"

#include <algorithm>
#include <cmath>

namespace cooperage::pave::detail {
namespace {

/// Node -> the quads using it, in quad order, as compressed rows (one
/// allocation instead of one vector per node).
struct QuadsOf {
  std::vector<int> start, items;
  struct Row {
    const int* b;
    const int* e;
    const int* begin() const { return b; }
    const int* end() const { return e; }
    size_t size() const { return static_cast<size_t>(e - b); }
    int operator[](size_t k) const { return b[k]; }
  };
  QuadsOf(size_t n, const std::vector<Quad>& quads) : start(n + 1, 0) {
    for (const Quad& q : quads) {
      for (int v : q) {
        if (v >= 0) ++start[static_cast<size_t>(v) + 1];
      }
    }
    for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    items.resize(static_cast<size_t>(start[n]));
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int k = 0; k < static_cast<int>(quads.size()); ++k) {
      for (int v : quads[static_cast<size_t>(k)]) {
        if (v >= 0) items[static_cast<size_t>(fill[static_cast<size_t>(v)]++)] = k;
      }
    }
  }
  Row operator[](size_t i) const {
    return Row{items.data() + start[i], items.data() + start[i + 1]};
  }
};

/// Drops nodes no quad uses (never fixed ones), keeping the node order.
void compact(std::vector<Eigen::Vector2d>& pts, std::vector<Quad>& quads,
             std::vector<char>& fixed) {
  const size_t n = pts.size();
  std::vector<int> used(n, 0);
  for (const Quad& q : quads) {
    for (int v : q) used[static_cast<size_t>(v)] = 1;
  }
  std::vector<int> remap(n, -1);
  int next = 0;
  for (size_t i = 0; i < n; ++i) {
    if (used[i] || fixed[i]) {
      remap[i] = next;
      pts[static_cast<size_t>(next)] = pts[i];
      fixed[static_cast<size_t>(next)] = fixed[i];
      ++next;
    }
  }
  pts.resize(static_cast<size_t>(next));
  fixed.resize(static_cast<size_t>(next));
  for (Quad& q : quads) {
    for (int& v : q) v = remap[static_cast<size_t>(v)];
  }
}

}  // namespace

int collapse_diamonds(std::vector<Eigen::Vector2d>& pts, std::vector<Quad>& quads,
                      std::vector<char>& fixed) {
  const size_t n = pts.size();
  const QuadsOf of(n, quads);
  std::vector<Quad> trial;
  std::vector<char> touched(quads.size(), 0), dead(quads.size(), 0);
  int collapsed = 0;
  for (int k = 0; k < static_cast<int>(quads.size()); ++k) {
    if (touched[static_cast<size_t>(k)]) continue;
    for (int r = 0; r < 2; ++r) {
      const Quad q = quads[static_cast<size_t>(k)];
      const int a = q[static_cast<size_t>(r)], b = q[static_cast<size_t>(r + 1)];
      const int c = q[static_cast<size_t>(r + 2)], d = q[static_cast<size_t>((r + 3) % 4)];
      const QuadsOf::Row qa = of[static_cast<size_t>(a)];
      const QuadsOf::Row qc = of[static_cast<size_t>(c)];
      if (fixed[static_cast<size_t>(a)] || fixed[static_cast<size_t>(c)] || qa.size() != 3 ||
          qc.size() != 3)
        continue;
      if (of[static_cast<size_t>(b)].size() + of[static_cast<size_t>(d)].size() < 9) continue;
      bool free_ok = true;
      for (int x : qa)
        free_ok = free_ok && !touched[static_cast<size_t>(x)] &&
                  (x == k || std::find(qc.begin(), qc.end(), x) == qc.end());
      for (int x : qc) free_ok = free_ok && !touched[static_cast<size_t>(x)];
      if (!free_ok) continue;
      // Merge c into a at the middle of the diagonal; keep it only if a's
      // four quads stay valid.
      const Eigen::Vector2d saved = pts[static_cast<size_t>(a)];
      pts[static_cast<size_t>(a)] = 0.5 * (saved + pts[static_cast<size_t>(c)]);
      trial.clear();
      for (int x : qa) {
        if (x != k) trial.push_back(quads[static_cast<size_t>(x)]);
      }
      for (int x : qc) {
        if (x == k) continue;
        Quad t = quads[static_cast<size_t>(x)];
        for (int& v : t) {
          if (v == c) v = a;
        }
        trial.push_back(t);
      }
      bool valid = true;
      for (const Quad& t : trial) valid = valid && scaled_jacobian_2d(pts, t) > 0.05;
      if (!valid) {
        pts[static_cast<size_t>(a)] = saved;
        continue;
      }
      for (int x : qc) {
        if (x == k) continue;
        for (int& v : quads[static_cast<size_t>(x)]) {
          if (v == c) v = a;
        }
      }
      for (int x : qa) touched[static_cast<size_t>(x)] = 1;
      for (int x : qc) touched[static_cast<size_t>(x)] = 1;
      dead[static_cast<size_t>(k)] = 1;
      ++collapsed;
      break;
    }
  }
  if (collapsed == 0) return 0;
  std::vector<Quad> kept;
  kept.reserve(quads.size());
  for (size_t k = 0; k < quads.size(); ++k) {
    if (!dead[k]) kept.push_back(quads[k]);
  }
  quads.swap(kept);
  compact(pts, quads, fixed);
  return collapsed;
}

int remove_doublets(std::vector<Eigen::Vector2d>& pts, std::vector<Quad>& quads,
                    std::vector<char>& fixed) {
  const size_t n = pts.size();
  int removed = 0;
  for (int pass = 0; pass < 4; ++pass) {
    const QuadsOf of(n, quads);
    std::vector<char> dead(quads.size(), 0);
    int here = 0;
    for (size_t i = 0; i < n; ++i) {
      if (fixed[i] || of[i].size() != 2) continue;
      const int k1 = of[i][0], k2 = of[i][1];
      if (dead[static_cast<size_t>(k1)] || dead[static_cast<size_t>(k2)]) continue;
      Quad a = quads[static_cast<size_t>(k1)], b = quads[static_cast<size_t>(k2)];
      while (a[0] != static_cast<int>(i)) std::rotate(a.begin(), a.begin() + 1, a.end());
      while (b[0] != static_cast<int>(i)) std::rotate(b.begin(), b.begin() + 1, b.end());
      // a = (i, x, y, z), b = (i, z, w, x) for a doublet.
      if (b[1] != a[3] || b[3] != a[1]) continue;
      const Quad merged{a[1], a[2], a[3], b[2]};
      if (scaled_jacobian_2d(pts, merged) < 0.05) continue;
      quads[static_cast<size_t>(k1)] = merged;
      quads[static_cast<size_t>(k2)] = {-1, -1, -1, -1};
      dead[static_cast<size_t>(k1)] = dead[static_cast<size_t>(k2)] = 1;
      ++here;
    }
    if (here == 0) break;
    removed += here;
    std::vector<Quad> kept;
    kept.reserve(quads.size());
    for (const Quad& q : quads) {
      if (q[0] >= 0) kept.push_back(q);
    }
    quads.swap(kept);
  }
  compact(pts, quads, fixed);
  return removed;
}

int irregular_nodes(const std::vector<Eigen::Vector2d>& pts, const std::vector<Quad>& quads,
                    const std::vector<char>& fixed) {
  const size_t n = pts.size();
  std::vector<int> valence(n, 0);
  std::vector<double> angle(n, 0.0);
  for (const Quad& q : quads) {
    for (int c = 0; c < 4; ++c) {
      const size_t v = static_cast<size_t>(q[static_cast<size_t>(c)]);
      ++valence[v];
      const Eigen::Vector2d e0 =
          pts[static_cast<size_t>(q[static_cast<size_t>((c + 1) % 4)])] - pts[v];
      const Eigen::Vector2d e1 =
          pts[static_cast<size_t>(q[static_cast<size_t>((c + 3) % 4)])] - pts[v];
      angle[v] += std::atan2(cross2(e0, e1), e0.dot(e1));
    }
  }
  int irregular = 0;
  for (size_t i = 0; i < n; ++i) {
    if (valence[i] == 0) continue;
    if (!fixed[i]) {
      irregular += valence[i] != 4;
      continue;
    }
    const double deg = angle[i] * 180.0 / M_PI;
    const int ideal = deg < 135 ? 1 : deg < 225 ? 2 : deg < 315 ? 3 : 4;
    irregular += valence[i] != ideal;
  }
  return irregular;
}

}  // namespace cooperage::pave::detail
