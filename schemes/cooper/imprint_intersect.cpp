// Subcap intersection (Blacker 1996, sec. 5.3): a subcap whose gap reaches
// two opposing subcaps, and subcaps without ribs that overlap; the
// intersection node p is the closest one meeting even parity.
#include "schemes/cooper/imprinter.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <functional>
#include <limits>

namespace cooperage::cooper::detail {

bool Imprinter::crosses_opposing(int e, const Loop& la) {
  for (const Subcap& b : caps(1 - e)) {
    if (matched(b.id)) continue;
    for (const Loop& lb : b.loops) {
      for (size_t i = 0; i < la.size(); ++i) {
        for (size_t k = 0; k < lb.size(); ++k) {
          if (segment_hit(xy().at(la[i]), xy().at(la[(i + 1) % la.size()]), xy().at(lb[k]),
                          xy().at(lb[(k + 1) % lb.size()]))) {
            return true;
          }
        }
      }
    }
  }
  return false;
}

// A free loop crossing opposing boundaries (overlapping subcaps without
// ribs, sec. 5.3): each crossing is combined onto an unribbed node of a and
// an unribbed, non-exterior opposing node next to it (sec. 5.4), giving a's
// loop ribs; the gaps between them are then subtracted. Even parity (sec.
// 5.3: "this intersection node must meet the even parity constraint"): of
// the two nodes of a crossed segment, the one that leaves an even number of
// edges since the previous crossing along the loop -- every arc between two
// links even on both loops, so every piece they bound is even (each loop is
// even to begin with).
bool Imprinter::free_crossing(int e, const Subcap& a) {
  const Loop& la = a.loops.front();
  const size_t na = la.size();
  struct Crossing {
    size_t ia;  // segment la[ia] - la[ia + 1]
    double ta;
    Loop lb;    // the opposing loop
    size_t kb;  // segment lb[kb] - lb[kb + 1]
    double tb;
    Vec2 x;
    int va = -1, vb = -1;
  };
  std::vector<Crossing> found;
  for (size_t i = 0; i < na; ++i) {
    const Vec2& p0 = xy().at(la[i]);
    const Vec2& p1 = xy().at(la[(i + 1) % na]);
    const double h = (p1 - p0).norm();
    for (const Subcap& b : caps(1 - e)) {
      if (matched(b.id)) continue;
      for (const Loop& lb : b.loops) {
        for (size_t k = 0; k < lb.size(); ++k) {
          const Vec2& q0 = xy().at(lb[k]);
          const Vec2& q1 = xy().at(lb[(k + 1) % lb.size()]);
          const auto t = segment_hit(p0, p1, q0, q1);
          if (!t) continue;
          const Vec2 X = p0 + *t * (p1 - p0);
          bool seen = false;
          for (const Crossing& c : found) seen = seen || (c.x - X).norm() < 0.5 * h;
          if (seen) continue;
          const auto tb = segment_hit(q0, q1, p0, p1);
          found.push_back({i, *t, lb, k, tb ? *tb : 0.0, X});
        }
      }
    }
  }
  if (found.empty()) return false;
  auto edges = [](const Loop& l, int from, int to) {
    const long n = static_cast<long>(l.size());
    return ((index_in(l, to) - index_in(l, from)) % n + n) % n;
  };
  // The nodes of a chain of crossed segments along loop `l` (candidates per
  // crossing, in loop order) when the first takes candidate `first`, every
  // later one the candidate leaving an even arc behind it (or, when that one
  // is not free, the other); -1 where none is free.
  auto chain = [&](const Loop& l, const std::vector<std::array<int, 2>>& cands, int first,
                   const std::function<bool(int)>& free) {
    std::vector<int> out(cands.size(), -1);
    int prev = -1;
    for (size_t j = 0; j < cands.size(); ++j) {
      std::array<int, 2> order = cands[j];
      if (j == 0) {
        if (first == 1) std::swap(order[0], order[1]);
      } else if (prev >= 0 && options_.even_parity && edges(l, prev, order[0]) % 2 != 0) {
        std::swap(order[0], order[1]);
      }
      for (int v : order) {
        if (out[j] < 0 && free(v)) out[j] = v;
      }
      if (out[j] >= 0) prev = out[j];
    }
    return out;
  };
  // a's side: two parity-consistent choices.
  std::vector<std::array<int, 2>> ca;
  for (const Crossing& c : found) ca.push_back({la[c.ia], la[(c.ia + 1) % na]});
  const auto free_a = [&](int v) { return !partner(e, v).has_value(); };
  const std::vector<int> a_choice[2] = {chain(la, ca, 0, free_a), chain(la, ca, 1, free_a)};
  // Each opposing loop: its crossings in its own order, two choices each.
  std::map<std::set<int>, std::vector<size_t>> by_loop;
  for (size_t j = 0; j < found.size(); ++j)
    by_loop[std::set<int>(found[j].lb.begin(), found[j].lb.end())].push_back(j);
  const auto free_b = [&](int v) { return !partner(1 - e, v).has_value() && !exterior_.count(v); };
  std::vector<std::vector<size_t>> loop_members;
  std::vector<std::array<std::vector<int>, 2>> b_choice;
  for (auto& [key, list] : by_loop) {
    std::sort(list.begin(), list.end(), [&](size_t x, size_t y) {
      return found[x].kb != found[y].kb ? found[x].kb < found[y].kb : found[x].tb < found[y].tb;
    });
    const Loop& lb = found[list.front()].lb;
    std::vector<std::array<int, 2>> cb;
    for (size_t j : list) cb.push_back({lb[found[j].kb], lb[(found[j].kb + 1) % lb.size()]});
    loop_members.push_back(list);
    b_choice.push_back({chain(lb, cb, 0, free_b), chain(lb, cb, 1, free_b)});
  }
  // Two crossings on one opposing loop (a round boss over a square foot):
  // the lens and the pieces beside it are even exactly when the arcs
  // between the two links, one on each loop, sum to an even count; any of
  // the 16 choices with that, the shortest links. More crossings: every
  // arc even on both loops (the two chains per loop above).
  if (found.size() == 2 && loop_members.size() == 1) {
    const Loop& lb = found.front().lb;
    double best = std::numeric_limits<double>::infinity();
    for (int m = 0; m < 16; ++m) {
      const int a0 = ca[0][m & 1], a1 = ca[1][(m >> 1) & 1];
      const int b0 = lb[(found[0].kb + ((m >> 2) & 1)) % lb.size()];
      const int b1 = lb[(found[1].kb + ((m >> 3) & 1)) % lb.size()];
      if (a0 == a1 || b0 == b1 || !free_a(a0) || !free_a(a1) || !free_b(b0) || !free_b(b1))
        continue;
      if (options_.even_parity && (edges(la, a0, a1) + edges(lb, b0, b1)) % 2 != 0) continue;
      const double cost = (xy().at(a0) - xy().at(b0)).norm() + (xy().at(a1) - xy().at(b1)).norm();
      if (!(cost < best)) continue;
      best = cost;
      found[0].va = a0;
      found[0].vb = b0;
      found[1].va = a1;
      found[1].vb = b1;
    }
    loop_members.clear();  // chosen
  }
  // The cheapest combination: the links as short as possible.
  const size_t combos = loop_members.empty() ? 0 : size_t{2} << loop_members.size();
  double best_cost = std::numeric_limits<double>::infinity();
  for (size_t m = 0; m < combos; ++m) {
    std::vector<int> va = a_choice[m & 1], vb(found.size(), -1);
    for (size_t l = 0; l < loop_members.size(); ++l) {
      const auto& pick = b_choice[l][(m >> (l + 1)) & 1];
      for (size_t k = 0; k < loop_members[l].size(); ++k) vb[loop_members[l][k]] = pick[k];
    }
    std::set<int> used;
    double cost = 0;
    bool ok = true;
    for (size_t j = 0; j < found.size(); ++j) {
      if (va[j] < 0 || vb[j] < 0) continue;
      ok = ok && used.insert(va[j]).second && used.insert(vb[j]).second;
      cost += (xy().at(va[j]) - xy().at(vb[j])).norm();
    }
    if (!ok || !(cost < best_cost)) continue;
    best_cost = cost;
    for (size_t j = 0; j < found.size(); ++j) {
      found[j].va = va[j];
      found[j].vb = vb[j];
    }
  }
  int links = 0;
  for (const Crossing& c : found) {
    if (c.va < 0 || c.vb < 0) continue;
    link(e, c.va, c.vb);
    r_.seams.push_back({c.va, c.vb});
    r_.steps.push_back(ImprintStep::Seam);
    ++links;
  }
  if (links > 0) r_.steps.push_back(ImprintStep::Intersect);
  return links > 0;
}

// Splits subcap bi of end e along a path x -> path -> y between two nodes
// of one of its hole loops: the piece between the path and one arc of the
// hole becomes a subcap, the hole grows by it (sec. 5.2-5.3).
bool Imprinter::split_hole(int e, size_t bi, int x, const Loop& path, int y) {
  Subcap& t = caps(e)[bi];
  for (size_t h = 1; h < t.loops.size(); ++h) {
    const Loop H = t.loops[h];
    const int ix = index_in(H, x), iy = index_in(H, y);
    if (ix < 0 || iy < 0 || ix == iy) continue;
    const size_t n = H.size();
    Loop fwd, bwd;  // arcs of H from y to x, exclusive
    for (size_t k = (static_cast<size_t>(iy) + 1) % n; k != static_cast<size_t>(ix);
         k = (k + 1) % n)
      fwd.push_back(H[k]);
    for (size_t k = (static_cast<size_t>(iy) + n - 1) % n; k != static_cast<size_t>(ix);
         k = (k + n - 1) % n)
      bwd.push_back(H[k]);
    Loop base{x};
    base.insert(base.end(), path.begin(), path.end());
    base.push_back(y);
    Loop c1 = base, c2 = base;
    c1.insert(c1.end(), fwd.begin(), fwd.end());
    c2.insert(c2.end(), bwd.begin(), bwd.end());
    // The piece does not enclose the other arc.
    auto encloses = [&](const Loop& c, const Loop& arc) {
      return !arc.empty() && point_in_loop(xy().at(arc[arc.size() / 2]), c, xy());
    };
    Loop piece = encloses(c1, bwd) ? c2 : c1;
    Loop hole = encloses(c1, bwd) ? c1 : c2;
    if (signed_area(piece, xy()) < 0) std::reverse(piece.begin(), piece.end());
    if (signed_area(hole, xy()) > 0) std::reverse(hole.begin(), hole.end());
    t.loops[h] = hole;
    // Other holes of t inside the piece go with it (a foot inside a boss
    // whose image splits t from the hole of a blind hole's floor).
    std::vector<Loop> piece_loops{piece}, kept;
    for (size_t k = 0; k < t.loops.size(); ++k) {
      const Loop& other = t.loops[k];
      const auto free_node =
          std::find_if(other.begin(), other.end(), [&](int v) { return index_in(piece, v) < 0; });
      const bool inside = k != 0 && k != h && free_node != other.end() &&
                          point_in_loop(xy().at(*free_node), piece, xy());
      (inside ? piece_loops : kept).push_back(other);
    }
    t.loops = std::move(kept);
    new_cap(e, std::move(piece_loops), t.id);
    r_.steps.push_back(ImprintStep::Subtract);
    return true;
  }
  return false;
}

// sec. 5.3: the gap's ends reach two subcaps, b (at r1) and c (at r0).
bool Imprinter::intersect(int e, const Subcap& a, int r0, const Loop& gap, int r1,
                          const std::vector<int>& hx, const std::vector<int>& hy) {
  if (hx.empty() || hy.empty()) return false;
  const int o = 1 - e;
  const int x = *partner(e, r0);
  const int y = *partner(e, r1);
  const size_t bi = static_cast<size_t>(hy.front());
  const Subcap b = caps(o)[bi];
  const Subcap c = caps(o)[static_cast<size_t>(hx.front())];
  const Loop& bl = b.loops.front();
  const size_t bn = bl.size();
  // Gamma_ba + the b/c boundary S: b's loop forward from y.
  const int iy = index_in(bl, y);
  std::vector<int> walk;  // y ... s0 ... s_t
  std::set<int> cset;
  for (const Loop& l : c.loops) cset.insert(l.begin(), l.end());
  size_t s0 = bn;
  for (size_t k = 0; k < bn; ++k) {
    const int v = bl[(static_cast<size_t>(iy) + k) % bn];
    if (s0 == bn) {
      walk.push_back(v);
      if (cset.count(v)) s0 = walk.size() - 1;
    } else if (cset.count(v)) {
      walk.push_back(v);
    } else {
      break;
    }
  }
  if (s0 == bn || walk.size() < s0 + 2) return false;
  // Projected gap Q = x, gap..., y; find its first crossing with S.
  std::vector<Vec2> q{xy().at(x)};
  for (int v : gap) q.push_back(xy().at(v));
  q.push_back(xy().at(y));
  size_t qi = 0, sj = 0;
  double best_t = 2;
  bool hit = false;
  for (size_t i = 0; i + 1 < q.size() && !hit; ++i) {
    for (size_t j = s0; j + 1 < walk.size(); ++j) {
      const auto t = segment_hit(q[i], q[i + 1], xy().at(walk[j]), xy().at(walk[j + 1]));
      if (t && (!hit || *t < best_t)) {
        hit = true;
        best_t = *t;
        qi = i;
        sj = j;
      }
    }
  }
  if (!hit) return false;
  const Vec2 X = q[qi] + best_t * (q[qi + 1] - q[qi]);
  // Candidates for the intersection node p (sec. 5.3): a node of S next to
  // the crossing, combined with a gap node next to it (g >= 0) or inserted
  // on the crossed edge of a (g < 0); closest first, even parity kept.
  struct Cand {
    long g;
    size_t pj;
    double d;
  };
  std::vector<Cand> cands;
  const size_t asize = caps(e)[index_of_cap(e, a.id)].loops.front().size();
  for (size_t pj : {sj, sj + 1}) {
    if (pj <= s0 || pj >= walk.size()) continue;
    const int p = walk[pj];
    if (partner_[o].count(p) || exterior_.count(p)) continue;
    for (long g : {static_cast<long>(qi) - 1, static_cast<long>(qi)}) {
      if (g < 0 || g >= static_cast<long>(gap.size())) continue;
      cands.push_back({g, pj, (xy().at(gap[static_cast<size_t>(g)]) - xy().at(p)).norm()});
    }
    // A node inserted on an edge of a model curve would break its mesh.
    const int e0 = qi == 0 ? r0 : gap[qi - 1];
    const int e1 = qi < gap.size() ? gap[qi] : r1;
    if (!(r_.ends.fixed.count(e0) && r_.ends.fixed.count(e1)))
      cands.push_back({-1, pj, (X - xy().at(p)).norm() + 1e-12});
  }
  std::stable_sort(cands.begin(), cands.end(),
                   [](const Cand& u, const Cand& v) { return u.d < v.d; });
  for (const Cand& cand : cands) {
    const size_t pj = cand.pj;
    const int p = walk[pj];
    const size_t first_b = cand.g >= 0 ? static_cast<size_t>(cand.g) + 1 : qi;
    const size_t kept = gap.size() > first_b ? gap.size() - first_b : 0;
    const size_t count = (pj + 1) + kept;  // nodes of a^
    if (options_.even_parity) {
      if (count % 2 != 0) continue;
      // An inserted node makes a's remainder odd when a is even.
      if (cand.g < 0 && (asize + 1 - count + 2) % 2 != 0) continue;
    }
    int p_up;
    if (cand.g >= 0) {
      p_up = gap[static_cast<size_t>(cand.g)];
      partner_[e][p_up] = p;
      partner_[o][p] = p_up;
      r_.seams.push_back({p_up, p});
      r_.steps.push_back(ImprintStep::Seam);
    } else {
      p_up = next_node_++;
      r_.ends.xy[p_up] = xy().at(p);
      const int u0 = qi == 0 ? r0 : gap[qi - 1];
      const int u1 = qi < gap.size() ? gap[qi] : r1;
      insert_on_edge(e, u0, u1, p_up);
      link(o, p, p_up);
    }
    // Lower side: a^ = b split by p -> projected gap[first_b ..] -> y.
    Loop low_path;
    for (size_t g = first_b; g < gap.size(); ++g)
      low_path.push_back(project(e, gap[g], a.loops.front()));
    // Upper side: project Gamma_bp (walk up to p) where it has no rib.
    Loop up_path;
    int ja = -1;
    for (size_t k = 0; k < pj; ++k) {
      const int v = walk[k];
      if (const auto pv = partner(o, v); pv && k <= s0) {
        ja = *pv;
        up_path.clear();
      } else {
        up_path.push_back(project(o, v, bl));
      }
    }
    if (ja < 0) return false;
    const size_t ai = index_of_cap(e, a.id);
    const Loop aouter = caps(e)[ai].loops.front();
    const Loop bouter = caps(o)[index_of_cap(o, b.id)].loops.front();
    // The crossing's walk can end on a hole of a, not its outer loop (seed
    // 30 case 83): there is no split of the outer loop then, and the state
    // so far (ribs, the node on the edge) is no base for another step.
    if (index_in(aouter, ja) < 0 || index_in(aouter, p_up) < 0 || index_in(bouter, p) < 0 ||
        index_in(bouter, y) < 0) {
      abandoned_ = "two subcaps' loops cross where neither outer loop can be split";
      return true;
    }
    auto [a_left, a_right] = split_loop(aouter, ja, up_path, p_up);
    auto [b_left, b_right] = split_loop(bouter, p, low_path, y);
    const auto a_ids = replace(e, ai, {a_left, a_right});
    const auto b_ids = replace(o, index_of_cap(o, b.id), {b_left, b_right});
    if (!a_ids.empty() && !b_ids.empty()) {
      match_of_[a_ids.front()] = b_ids.front();
      match_of_[b_ids.front()] = a_ids.front();
    }
    r_.steps.push_back(ImprintStep::Intersect);
    return true;
  }
  return false;
}

size_t Imprinter::index_of_cap(int e, int id) {
  auto& list = caps(e);
  for (size_t i = 0; i < list.size(); ++i) {
    if (list[i].id == id) return i;
  }
  return list.size();
}

void Imprinter::insert_on_edge(int e, int u, int v, int w) {
  for (Subcap& s : caps(e)) {
    for (Loop& l : s.loops) {
      const size_t n = l.size();
      for (size_t k = 0; k < n; ++k) {
        if ((l[k] == u && l[(k + 1) % n] == v) || (l[k] == v && l[(k + 1) % n] == u)) {
          l.insert(l.begin() + static_cast<long>(k + 1), w);
          break;
        }
      }
    }
  }
}

}  // namespace cooperage::cooper::detail
