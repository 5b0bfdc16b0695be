#include "schemes/cooper/imprint_subcaps.h"

#include "schemes/cooper/imprinter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

namespace cooperage::cooper {

const char* to_string(ImprintStep step) {
  switch (step) {
    case ImprintStep::Match: return "match";
    case ImprintStep::Subtract: return "subtract";
    case ImprintStep::Intersect: return "intersect";
    case ImprintStep::Seam: return "seam";
    case ImprintStep::SelfIntersect: return "self-intersect";
  }
  return "?";
}

namespace detail {
namespace {

// Steps allowed beyond one per node of the barrel's ends.
constexpr int kStepsBeyondNodes = 100;

}  // namespace

Imprinter::Imprinter(const BarrelEnds& in, const ImprintOptions& options) : options_(options) {
  r_.ends = in;
  for (const auto& [id, p] : in.xy) next_node_ = std::max(next_node_, id + 1);
  first_new_node_ = next_node_;
  for (const auto* list : {&in.upper, &in.lower}) {
    for (const Subcap& s : *list) next_cap_ = std::max(next_cap_, s.id + 1);
  }
  for (const auto& [u, l] : in.ribs) {
    partner_[0][u] = l;
    partner_[1][l] = u;
    exterior_.insert(u);
    exterior_.insert(l);
  }
}

ImprintResult Imprinter::run() {
  // Imprinting that goes on far longer than the ends have nodes is going
  // round in circles (a subcap split again and again): the campaign's
  // imprints take at most 15 steps, real CAD's at most 53 on 1,212 nodes,
  // and a cycle ran to 10,000 steps for 7.7 s before it gave up.
  const int bound =
      std::min(options_.max_steps, kStepsBeyondNodes + static_cast<int>(r_.ends.xy.size()));
  for (int step = 0; step < bound; ++step) {
    if (step < options_.trace_steps) {
      BarrelEnds now = r_.ends;
      now.ribs = ribs_so_far();
      r_.trace.emplace_back(std::move(now),
                            r_.steps.empty() ? std::string("start") : to_string(r_.steps.back()));
    }
    if (!abandoned_.empty()) {
      r_.why = abandoned_ + "; unmatched subcaps" + unmatched_list();
      r_.summary = abandoned_;
      export_ribs();
      return r_;
    }
    // A loop beside a combined crossing (sec. 5.3) may now walk to it and
    // back: a pocket's edge over a round hole's lens, both ends of it.
    for (int e = 0; e < 2; ++e) {
      for (Subcap& c : caps(e)) {
        for (Loop& l : c.loops) version_ += remove_spikes(l) ? 1 : 0;
        version_ += merge_touching_holes(c.loops) ? 1 : 0;
      }
    }
    if (all_matched()) {
      finish();
      return r_;
    }
    if (try_matches()) continue;
    // Before the gaps: a subtraction would cut a zero-area sliver along it.
    if (try_coincident()) continue;
    if (try_gaps()) continue;
    r_.why = "no imprinting step applies to the unmatched subcaps" + unmatched_list();
    r_.summary = "no imprinting step applies to the " + left_unmatched();
    export_ribs();
    return r_;
  }
  r_.why = "imprinting did not finish within " + std::to_string(bound) +
           " steps; unmatched subcaps" + unmatched_list();
  r_.summary = "imprinting did not finish within " + std::to_string(bound) + " steps (" +
               left_unmatched() + ")";
  export_ribs();
  return r_;
}

std::vector<std::pair<int, int>> Imprinter::ribs_so_far() const {
  std::vector<std::pair<int, int>> ribs;
  ribs.reserve(partner_[0].size());
  for (const auto& [u, l] : partner_[0]) ribs.push_back({u, l});
  return ribs;
}

void Imprinter::export_ribs() { r_.ends.ribs = ribs_so_far(); }

bool Imprinter::all_matched() {
  for (int e = 0; e < 2; ++e) {
    for (const Subcap& s : caps(e)) {
      if (!matched(s.id)) return false;
    }
  }
  return true;
}

std::string Imprinter::unmatched_list() {
  // The first few by id (r_.unmatched holds them all): a cycle of splits
  // left 240 subcaps, a 2 KB line no person reads.
  constexpr size_t kListed = 8;
  std::string s;
  size_t count = 0;
  for (int e = 0; e < 2; ++e) {
    for (const Subcap& c : caps(e)) {
      if (matched(c.id)) continue;
      if (count++ < kListed)
        s +=
            std::string(s.empty() ? ": " : ", ") + (e ? "lower " : "upper ") + std::to_string(c.id);
      r_.unmatched[static_cast<size_t>(e)].push_back(c.id);
    }
  }
  if (count > kListed) s += " and " + std::to_string(count - kListed) + " more";
  return s;
}

std::string Imprinter::left_unmatched() const {
  const size_t n = r_.unmatched[0].size() + r_.unmatched[1].size();
  return std::to_string(n) + (n == 1 ? " subcap" : " subcaps") + " left unmatched";
}

void Imprinter::finish() {
  r_.ok = true;
  for (const Subcap& s : r_.ends.upper) r_.matches.push_back({s.id, match_of_.at(s.id)});
  std::sort(r_.matches.begin(), r_.matches.end());
  export_ribs();
}

std::optional<int> Imprinter::partner(int e, int node) const {
  const auto it = partner_[e].find(node);
  if (it == partner_[e].end()) return std::nullopt;
  return it->second;
}

void Imprinter::link(int e, int node, int other) {
  ++version_;
  partner_[e][node] = other;
  partner_[1 - e][other] = node;
  r_.interior_ribs.push_back(e == 0 ? std::make_pair(node, other) : std::make_pair(other, node));
}

// Unmatched subcaps of end e whose loops contain node.
std::vector<int> Imprinter::holders(int e, int node) {
  std::vector<int> out;
  auto& list = caps(e);
  for (size_t i = 0; i < list.size(); ++i) {
    if (matched(list[i].id)) continue;
    for (const Loop& l : list[i].loops) {
      if (index_in(l, node) >= 0) {
        out.push_back(static_cast<int>(i));
        break;
      }
    }
  }
  return out;
}

// sec. 5.1: a is fully ribbed into b and b into a, loop for loop.
bool Imprinter::try_matches() {
  auto& up = caps(0);
  auto& lo = caps(1);
  for (const Subcap& a : up) {
    if (matched(a.id)) continue;
    std::set<int> image;
    bool full = true;
    for (const Loop& l : a.loops) {
      for (int v : l) {
        const auto p = partner(0, v);
        if (!p)
          full = false;
        else
          image.insert(*p);
      }
    }
    if (!full) continue;
    for (const Subcap& b : lo) {
      if (matched(b.id) || b.loops.size() != a.loops.size()) continue;
      std::set<int> nodes;
      for (const Loop& l : b.loops) nodes.insert(l.begin(), l.end());
      if (nodes != image) continue;
      match_of_[a.id] = b.id;
      match_of_[b.id] = a.id;
      r_.steps.push_back(ImprintStep::Match);
      return true;
    }
  }
  return false;
}

// Projects node v of end e onto end 1 - e (seaming onto an opposing node
// without a rib when close, sec. 5.4); returns the opposing node.
int Imprinter::project(int e, int v, const Loop& around, bool seam) {
  if (const auto p = partner(e, v)) return *p;
  const Vec2 x = xy().at(v);
  double h = std::numeric_limits<double>::infinity();
  const int i = index_in(around, v);
  if (i >= 0) {
    const size_t n = around.size();
    h = std::min((xy().at(around[(static_cast<size_t>(i) + 1) % n]) - x).norm(),
                 (xy().at(around[(static_cast<size_t>(i) + n - 1) % n]) - x).norm());
  }
  const double tol = seam && std::isfinite(h) ? options_.seam_fraction * h : 0.0;
  int best = -1;
  double best_d = tol;
  for (const Subcap& s : caps(1 - e)) {
    if (matched(s.id)) continue;
    for (const Loop& l : s.loops) {
      for (int w : l) {
        if (partner_[1 - e].count(w) || exterior_.count(w)) continue;
        const double d = (xy().at(w) - x).norm();
        if (d < best_d) {
          best_d = d;
          best = w;
        }
      }
    }
  }
  if (best >= 0) {
    link(e, v, best);
    r_.interior_ribs.pop_back();  // a seam, not a new rib node
    r_.interior_ribs.push_back(e == 0 ? std::make_pair(v, best) : std::make_pair(best, v));
    r_.seams.push_back({v, best});
    r_.steps.push_back(ImprintStep::Seam);
    return best;
  }
  const int w = next_node_++;
  r_.ends.xy[w] = x;
  link(e, v, w);
  return w;
}

int Imprinter::new_cap(int e, std::vector<Loop> loops, int parent) {
  ++version_;
  Subcap s;
  s.id = next_cap_++;
  if (parent >= 0) {
    const auto root = r_.origin.find(parent);
    r_.origin[s.id] = root == r_.origin.end() ? parent : root->second;
  }
  s.loops = std::move(loops);
  caps(e).push_back(s);
  return s.id;
}

// Replaces subcap index `bi` of end e by outer loops `pieces`, handing
// out its holes to the piece containing them; returns their ids. Pieces
// that cross or touch themselves are resolved first (sec. 5.5).
std::vector<int> Imprinter::replace(int e, size_t bi, const std::vector<Loop>& pieces) {
  const Subcap old = caps(e)[bi];
  caps(e).erase(caps(e).begin() + static_cast<long>(bi));
  std::vector<Loop> outers, overlaps;
  std::vector<Loop> todo = pieces;
  const auto combinable = [&](int u, int v) { return !(partner(e, u) && partner(e, v)); };
  for (size_t pi = 0; pi < todo.size(); ++pi) {
    std::vector<std::pair<int, int>> combined;
    const auto parts =
        split_self_intersections(todo[pi], xy(), options_.even_parity, &combined, combinable);
    apply_combined(e, combined);
    // The other pieces share the split path: they lose the node too.
    for (const auto& [drop, keep] : combined) {
      for (size_t pj = pi + 1; pj < todo.size(); ++pj)
        std::replace(todo[pj].begin(), todo[pj].end(), drop, keep);
      for (auto* done : {&outers, &overlaps}) {
        for (Loop& l : *done) std::replace(l.begin(), l.end(), drop, keep);
      }
    }
    if (parts.size() > 1) r_.steps.push_back(ImprintStep::SelfIntersect);
    for (const Loop& part : parts) {
      // An absolute 1e-14 kept a flat piece, or dropped it, by the
      // rounding of chart coordinates: campaign seed 3 case 153 was
      // refused as built and meshed when moved.
      if (flat_loop(part, xy())) continue;
      (signed_area(part, xy()) > 0 ? outers : overlaps).push_back(part);
    }
  }
  std::vector<int> ids;
  std::vector<std::vector<Loop>> loops;
  for (const Loop& o : outers) loops.push_back({o});
  for (size_t h = 1; h < old.loops.size(); ++h) {
    const Loop& hole = old.loops[h];
    const Vec2 p = hole_owner_probe(hole, xy(), outers);
    for (auto& l : loops) {
      if (!point_in_loop(p, l.front(), xy())) continue;
      // A split path along the hole's nodes leaves it touching the piece.
      if (!absorb_touching_hole(l.front(), hole)) l.push_back(hole);
      break;
    }
  }
  for (auto& l : loops) ids.push_back(new_cap(e, l, old.id));
  for (const Loop& o : overlaps) subtract_overlap(e, Loop(o.rbegin(), o.rend()));
  return ids;
}

void Imprinter::apply_combined(int e, const std::vector<std::pair<int, int>>& combined) {
  for (const auto& [drop, keep] : combined) {
    for (Subcap& s : caps(e)) {
      for (Loop& l : s.loops) std::replace(l.begin(), l.end(), drop, keep);
    }
    const auto p = partner(e, drop);
    if (!p) {
      r_.seams.push_back({drop, keep});
      continue;
    }
    partner_[e].erase(drop);
    const auto q = partner(e, keep);
    // Given nodes stay: a model curve's, or a cap's that another barrel shares.
    const auto pinned = [&](int v) { return v < first_new_node_; };
    if (q && *q != *p && !(pinned(*p) && pinned(*q))) {
      // Both were ribbed (a crossing whose every node pair has ribs): one
      // node cannot sweep to two, so their images are combined as well,
      // or the ribs would stop being one-to-one and the next gaps would
      // re-imprint the dropped image for ever.
      const int image_drop = pinned(*p) ? *q : *p;
      const int image_keep = pinned(*p) ? *p : *q;
      for (Subcap& s : caps(1 - e)) {
        for (Loop& l : s.loops) std::replace(l.begin(), l.end(), image_drop, image_keep);
      }
      partner_[1 - e].erase(image_drop);
      partner_[e][keep] = image_keep;
      partner_[1 - e][image_keep] = keep;
      r_.seams.push_back({image_drop, image_keep});
    } else if (q && *q != *p) {
      // Both images given nodes: keep stays ribbed to its own, and drop's
      // image loses its rib (it pointed at a node no loop holds any more).
      partner_[1 - e].erase(*p);
    } else {
      partner_[e][keep] = *p;
      partner_[1 - e][*p] = keep;
    }
    r_.seams.push_back({drop, keep});
  }
}

// sec. 5.5: an overlap (a loop traversed clockwise after a subtraction)
// lies inside other subcaps; it is subtracted from each and becomes a subcap.
void Imprinter::subtract_overlap(int e, const Loop& piece) {
  int parent = -1;
  Vec2 c = Vec2::Zero();
  for (int v : piece) c += xy().at(v);
  c /= static_cast<double>(piece.size());
  auto& list = caps(e);
  for (size_t i = 0; i < list.size(); ++i) {
    Subcap& t = list[i];
    if (!point_in_subcap(c, t, xy())) continue;
    if (parent < 0) parent = t.id;
    const Loop& outer = t.loops.front();
    // The piece's chain off t's outer loop cuts t.
    const size_t n = piece.size();
    int start = -1;
    for (size_t k = 0; k < n; ++k) {
      if (index_in(outer, piece[k]) >= 0 && index_in(outer, piece[(k + 1) % n]) < 0)
        start = static_cast<int>(k);
    }
    if (start < 0) {
      t.loops.push_back(Loop(piece.rbegin(), piece.rend()));  // fully inside: a hole
    } else {
      Loop interior;
      size_t k = (static_cast<size_t>(start) + 1) % n;
      while (index_in(outer, piece[k]) < 0) {
        interior.push_back(piece[k]);
        k = (k + 1) % n;
      }
      const int x = piece[static_cast<size_t>(start)], y = piece[k];
      auto [left, right] = split_loop(outer, x, interior, y);
      std::set<int> ps(piece.begin(), piece.end());
      const Loop& keep = std::set<int>(left.begin(), left.end()) == ps ? right : left;
      t.loops.front() = keep;
    }
    if (matched(t.id)) {  // recategorise its former match too
      match_of_.erase(match_of_.at(t.id));
      match_of_.erase(t.id);
    }
  }
  new_cap(e, {piece}, parent);
}

// A gap of loop l of subcap s (end e): consecutive ribbed nodes r0 -> r1
// with the nodes between them unribbed (or none, when the partners are not
// adjacent on an opposing subcap).
bool Imprinter::try_gaps() {
  for (int e = 0; e < 2; ++e) {
    for (size_t si = 0; si < caps(e).size(); ++si) {
      if (matched(caps(e)[si].id)) continue;
      const Subcap s = caps(e)[si];
      const Loop& outer = s.loops.front();
      std::vector<size_t> ribbed;
      for (size_t k = 0; k < outer.size(); ++k) {
        if (partner(e, outer[k])) ribbed.push_back(k);
      }
      if (ribbed.empty()) {
        if (free_loop(e, s) || free_crossing(e, s)) return true;
        continue;
      }
      const size_t n = outer.size();
      ribbed = gap_anchors(e, outer, ribbed);
      for (size_t g = 0; g < ribbed.size(); ++g) {
        const size_t k0 = ribbed[g];
        const size_t k1 = ribbed[(g + 1) % ribbed.size()];
        Loop gap;
        for (size_t k = (k0 + 1) % n; k != k1; k = (k + 1) % n) gap.push_back(outer[k]);
        const int x = *partner(e, outer[k0]);
        const int y = *partner(e, outer[k1]);
        if (skipped_gap(e, gap, x, y, ribbed.size())) continue;
        const long before = version_;
        if (gap_step(e, s, outer[k0], gap, outer[k1]) && version_ != before) return true;
      }
      if (hole_loops(e, s)) return true;
    }
  }
  return false;
}

bool Imprinter::skipped_gap(int e, const Loop& gap, int x, int y, size_t anchors) {
  if (!gap.empty()) return false;
  return x == y || opposing_edge(e, x, y) || anchors == 1;
}

bool Imprinter::on_hole_only(int o, int node) {
  bool hole = false;
  for (const Subcap& b : caps(o)) {
    if (matched(b.id)) continue;
    if (index_in(b.loops.front(), node) >= 0) return false;
    for (size_t h = 1; h < b.loops.size(); ++h) hole = hole || index_in(b.loops[h], node) >= 0;
  }
  return hole;
}

// sec. 5.2 where a feature touches a hole (two bosses meeting at a corner:
// the top's remainder has an outer loop and a hole through one vertex; or a
// crossing combined onto a hole's nodes, sec. 5.3). A run of ribbed nodes
// whose partners lie only on one hole of the opposing end, one after the
// other along it, between two nodes whose partners do not, ends no gap: the
// gaps on either side form one path from the opposing outer loop through the
// hole's nodes back to it, which splits the opposing subcap (a path from an
// outer loop to a hole alone would not).
std::vector<size_t> Imprinter::gap_anchors(int e, const Loop& outer,
                                           const std::vector<size_t>& ribbed) {
  const size_t m = ribbed.size(), n = outer.size();
  if (m < 3) return ribbed;
  std::vector<char> hole_only(m);
  for (size_t g = 0; g < m; ++g) hole_only[g] = on_hole_only(1 - e, *partner(e, outer[ribbed[g]]));
  auto gap_between = [&](size_t g0, size_t g1) {
    Loop gap;
    for (size_t k = (ribbed[g0] + 1) % n; k != ribbed[g1]; k = (k + 1) % n) gap.push_back(outer[k]);
    return gap;
  };
  auto image = [&](size_t g) { return *partner(e, outer[ribbed[g]]); };
  std::vector<char> through(m, 0);
  for (size_t g = 0; g < m; ++g) {
    const size_t prev = (g + m - 1) % m;
    if (!hole_only[g] || hole_only[prev]) continue;  // not the start of a run
    size_t last = g;
    bool along = true;
    while (hole_only[(last + 1) % m] && (last + 1) % m != g) {
      const size_t step = (last + 1) % m;
      along = gap_between(last, step).empty() && opposing_edge(e, image(last), image(step));
      if (!along) break;
      last = step;
    }
    const size_t next = (last + 1) % m;
    if (!along || next == g || next == prev) continue;
    if (skipped_gap(e, gap_between(prev, g), image(prev), image(g), m) ||
        skipped_gap(e, gap_between(last, next), image(last), image(next), m))
      continue;
    for (size_t k = g;; k = (k + 1) % m) {
      through[k] = 1;
      if (k == last) break;
    }
  }
  std::vector<size_t> out;
  for (size_t g = 0; g < m; ++g) {
    if (!through[g]) out.push_back(ribbed[g]);
  }
  return out.size() >= 2 ? out : ribbed;
}

bool Imprinter::opposing_edge(int e, int x, int y) {
  for (const Subcap& b : caps(1 - e)) {
    if (matched(b.id)) continue;
    for (const Loop& l : b.loops) {
      if (adjacent(l, x, y)) return true;
    }
  }
  return false;
}

// sec. 5.2: `loop` (counter-clockwise, new nodes strictly inside subcap bi
// of end o) cuts it in two: bi keeps the outside with `loop` as a new hole,
// the new subcap is the inside with the holes of bi that lie in it (a bore
// inside a shoulder's imprinted footprint stays a hole of the footprint).
int Imprinter::subtract_inside(int o, size_t bi, const Loop& loop) {
  Subcap& b = caps(o)[bi];
  const int parent = b.id;
  std::vector<Loop> inner{loop};
  std::vector<Loop> kept{b.loops.front()};
  for (size_t h = 1; h < b.loops.size(); ++h) {
    const Loop& hole = b.loops[h];
    const bool in = std::all_of(hole.begin(), hole.end(), [&](int v) {
      return index_in(loop, v) >= 0 || point_in_loop(xy().at(v), loop, xy());
    });
    (in ? inner : kept).push_back(hole);
  }
  kept.push_back(Loop(loop.rbegin(), loop.rend()));
  b.loops = std::move(kept);
  return new_cap(o, std::move(inner), parent);
}

// sec. 5.2: a subcap without any rib projects inside one opposing subcap.
bool Imprinter::free_loop(int e, const Subcap& a) {
  const Vec2 p = xy().at(a.loops.front().front());
  auto& opp = caps(1 - e);
  // Only a loop that lies inside one opposing subcap is subtracted here; a
  // free loop crossing an opposing boundary is left to free_crossing().
  if (crosses_opposing(e, a.loops.front())) return false;
  for (size_t bi = 0; bi < opp.size(); ++bi) {
    if (matched(opp[bi].id) || !point_in_subcap(p, opp[bi], xy())) continue;
    const Undo undo = undo_point();
    std::vector<Loop> images;
    for (const Loop& l : a.loops) {
      Loop img;
      for (int v : l) img.push_back(project(e, v, l));
      images.push_back(img);
    }
    // An image a sliver from b's loops (chords of a foot's rim across a
    // boss's): its new nodes move off them, or meshing b's piece fails.
    keep_clear(images.front(), true, opp[bi].loops, undo.next_node);
    const int hat = subtract_inside(1 - e, bi, images.front());
    // a's holes without ribs: imprinted inside the hat as well (the subcaps
    // filling them are matched to their images later).
    for (size_t h = 1; h < images.size(); ++h) {
      const std::set<int> img(images[h].begin(), images[h].end());
      const size_t hi = index_of_cap(1 - e, hat);
      bool present = false;
      for (const Loop& l : caps(1 - e)[hi].loops)
        present = present || std::set<int>(l.begin(), l.end()) == img;
      if (!present) subtract_inside(1 - e, hi, Loop(images[h].rbegin(), images[h].rend()));
    }
    r_.steps.push_back(ImprintStep::Subtract);
    return true;
  }
  return false;
}

// Hole loops of a without ribs: projected as holes into the subcap of the
// opposing end that holds a's outer image, plus a subcap filling each.
bool Imprinter::hole_loops(int e, const Subcap& a) {
  for (size_t h = 1; h < a.loops.size(); ++h) {
    const Loop& l = a.loops[h];
    if (std::any_of(l.begin(), l.end(), [&](int v) { return partner(e, v).has_value(); })) continue;
    if (crosses_opposing(e, l)) continue;
    const Vec2 p = xy().at(l.front());
    auto& opp = caps(1 - e);
    for (size_t bi = 0; bi < opp.size(); ++bi) {
      if (matched(opp[bi].id) || !point_in_subcap(p, opp[bi], xy())) continue;
      Loop img;
      for (int v : l) img.push_back(project(e, v, l));
      subtract_inside(1 - e, bi, Loop(img.rbegin(), img.rend()));
      r_.steps.push_back(ImprintStep::Subtract);
      return true;
    }
  }
  return false;
}

bool Imprinter::try_coincident() {
  for (int e = 0; e < 2; ++e) {
    for (const Subcap& a : caps(e)) {
      if (matched(a.id)) continue;
      for (const Loop& l : a.loops) {
        if (coincident_loop(e, l)) return true;
      }
    }
  }
  return false;
}

// Seam tolerance as in project(): a fraction of the shorter edge at each node.
bool Imprinter::coincident_loop(int e, const Loop& la) {
  const size_t n = la.size();
  for (int v : la) {
    if (partner(e, v)) return false;
  }
  auto tol = [&](size_t i) {
    const Vec2& x = xy().at(la[i]);
    return options_.seam_fraction * std::min((xy().at(la[(i + 1) % n]) - x).norm(),
                                             (xy().at(la[(i + n - 1) % n]) - x).norm());
  };
  for (const Subcap& b : caps(1 - e)) {
    if (matched(b.id)) continue;
    for (const Loop& lb : b.loops) {
      if (lb.size() != n) continue;
      const bool free = std::none_of(lb.begin(), lb.end(), [&](int w) {
        return partner_[1 - e].count(w) > 0 || exterior_.count(w) > 0;
      });
      if (!free) continue;
      // The node of lb at la[0], then the same cyclic order either way round.
      long first = -1;
      for (size_t k = 0; k < n && first < 0; ++k) {
        if ((xy().at(lb[k]) - xy().at(la[0])).norm() < tol(0)) first = static_cast<long>(k);
      }
      if (first < 0) continue;
      for (const long step : {1L, -1L}) {
        auto at = [&](size_t i) {
          const long m = static_cast<long>(n);
          return lb[static_cast<size_t>(((first + step * static_cast<long>(i)) % m + m) % m)];
        };
        bool same = true;
        for (size_t i = 0; i < n && same; ++i)
          same = (xy().at(at(i)) - xy().at(la[i])).norm() < tol(i);
        if (!same) continue;
        for (size_t i = 0; i < n; ++i) {
          link(e, la[i], at(i));
          r_.interior_ribs.pop_back();  // seams, not new rib nodes
          r_.interior_ribs.push_back(e == 0 ? std::make_pair(la[i], at(i))
                                            : std::make_pair(at(i), la[i]));
          r_.seams.push_back({la[i], at(i)});
        }
        r_.steps.push_back(ImprintStep::Seam);
        return true;
      }
    }
  }
  return false;
}

Imprinter::Undo Imprinter::undo_point() const {
  return {r_.interior_ribs.size(), r_.seams.size(), r_.steps.size(), next_node_};
}

void Imprinter::roll_back(int e, const Loop& fresh, const Undo& undo) {
  for (int v : fresh) {
    const auto p = partner(e, v);
    if (!p) continue;
    partner_[e].erase(v);
    partner_[1 - e].erase(*p);
    if (*p >= undo.next_node) r_.ends.xy.erase(*p);
  }
  r_.interior_ribs.resize(undo.interior_ribs);
  r_.seams.resize(undo.seams);
  r_.steps.resize(undo.steps);
  next_node_ = undo.next_node;
}

// Nodes of `path` on a hole loop of b.
static long seams_onto_holes(const Loop& path, const Subcap& b) {
  std::set<int> on_holes;
  for (size_t h = 1; h < b.loops.size(); ++h) on_holes.insert(b.loops[h].begin(), b.loops[h].end());
  return std::count_if(path.begin(), path.end(), [&](int w) { return on_holes.count(w) > 0; });
}

bool Imprinter::gap_step(int e, const Subcap& a, int r0, const Loop& gap, int r1) {
  const int x = *partner(e, r0);
  const int y = *partner(e, r1);
  const auto hx = holders(1 - e, x);
  const auto hy = holders(1 - e, y);
  std::vector<int> common;
  for (int h : hx) {
    if (std::find(hy.begin(), hy.end(), h) != hy.end()) common.push_back(h);
  }
  if (common.empty()) return intersect(e, a, r0, gap, r1, hx, hy);
  // sec. 5.2 subtraction: project the gap into the common subcap that
  // holds the gap's first segment.
  const Vec2 probe = 0.5 * (xy().at(x) + (gap.empty() ? xy().at(y) : xy().at(gap.front())));
  size_t bi = static_cast<size_t>(common.front());
  for (int c : common) {
    if (point_in_subcap(probe, caps(1 - e)[static_cast<size_t>(c)], xy()))
      bi = static_cast<size_t>(c);
  }
  // The probe sees only the gap's first segment. Where a's loop crosses an
  // opposing loop at a shallow angle (the rims of a blind hole and of a
  // foot below it, nearly tangent), that segment can dip across the rim
  // while the rest of the gap runs on the other side: then the subcap that
  // holds most of the gap's nodes (their images land where they are unless
  // seamed) is the one the gap cuts.
  if (gap.size() >= 3) {
    auto votes = [&](size_t c) {
      return std::count_if(gap.begin(), gap.end(), [&](int v) {
        return point_in_subcap(xy().at(v), caps(1 - e)[c], xy());
      });
    };
    const long probed = votes(bi);
    for (int c : common) {
      const long n = votes(static_cast<size_t>(c));
      if (n > probed && 2 * n > static_cast<long>(gap.size())) bi = static_cast<size_t>(c);
    }
  }
  if (!gap.empty() && gap_leaves_subcap(e, gap, a.loops.front(), bi) &&
      (seam_gap_to_arc(e, gap, x, y, common) || gap_crossing(e, a, x, gap, y, bi)))
    return true;
  const Undo undo = undo_point();
  Loop fresh;  // the gap's nodes without a rib yet (a run through a hole has some)
  for (int v : gap) {
    if (!partner(e, v)) fresh.push_back(v);
  }
  Loop path;
  for (int v : gap) path.push_back(project(e, v, a.loops.front()));
  const Loop outer = caps(1 - e)[bi].loops.front();
  // Seams that put the path onto a hole of b at two nodes or more (a
  // boss's rim 0.07 of an element outside a foot's) would cut through
  // the hole: projected without seams, the path passes beside it.
  bool seamed = true;
  if (seams_onto_holes(path, caps(1 - e)[bi]) >= 2) {
    roll_back(e, fresh, undo);
    path.clear();
    for (int v : gap) path.push_back(project(e, v, a.loops.front(), false));
    seamed = false;
  }
  {
    Loop chain{x};
    chain.insert(chain.end(), path.begin(), path.end());
    chain.push_back(y);
    const Subcap& b = caps(1 - e)[bi];
    const bool clear = keep_clear(
        chain, false, std::vector<Loop>(b.loops.begin() + 1, b.loops.end()), undo.next_node);
    if (!clear &&
        (gap_through_hole(e, a.loops.front(), gap, path, seamed, x, y, bi, fresh, undo) ||
         gap_through_own_hole(e, a.loops.front(), gap, path, seamed, x, y, bi, fresh, undo)))
      return true;
  }
  // Seamed onto b's boundary throughout: no split, the ribs are the progress.
  bool on_loop = true;
  for (int v : path) on_loop = on_loop && index_in(outer, v) >= 0;
  if (on_loop && !path.empty()) {
    r_.steps.push_back(ImprintStep::Subtract);
    return true;
  }
  if (path.empty() && adjacent(outer, x, y)) return false;
  if (x == y && !path.empty()) {
    // a touches b's boundary at one node (a boss meeting the notch of
    // another at a corner): a's image is a hole of b through that node.
    Loop inside{x};
    inside.insert(inside.end(), path.begin(), path.end());
    if (signed_area(inside, xy()) < 0) std::reverse(inside.begin(), inside.end());
    subtract_inside(1 - e, bi, inside);
    r_.steps.push_back(ImprintStep::Subtract);
    return true;
  }
  if (index_in(outer, x) < 0 || index_in(outer, y) < 0) {
    if (split_pinched(1 - e, bi, x, path, y) || split_hole(1 - e, bi, x, path, y) ||
        join_holes(e, a, r0, path, r1, bi))
      return true;
    // No split: ribs to nodes on no subcap would end later gaps nowhere.
    roll_back(e, fresh, undo);
    return false;
  }
  auto [left, right] = split_loop(outer, x, path, y);
  // A piece that would be one quad with a straight corner (a vertex of a's
  // loop poking just across an opposing boundary that has a node there)
  // sweeps to a flat hex; seaming the gap onto that boundary instead leans
  // the ribs a little and cuts no piece.
  if ((flat_quad(left, xy()) || flat_quad(right, xy())) && seam_gap_to_arc(e, gap, x, y, common))
    return true;
  replace(1 - e, bi, {left, right});
  r_.steps.push_back(ImprintStep::Subtract);
  return true;
}

}  // namespace detail

// cite: Blacker 1996, sec. 5 (imprinting subcaps: 5.1-5.5).
ImprintResult imprint_subcaps(const BarrelEnds& ends, const ImprintOptions& options) {
  return detail::Imprinter(ends, options).run();
}

}  // namespace cooperage::cooper
