#include "schemes/cooper/cap_candidates.h"

#include "schemes/cooper/side_lattice.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace cooperage::cooper {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Largest deviation from flat tolerated between a cap and a subcap filling
// one of its hole loops.
constexpr double kSubcapFlatness = 15.0;

std::set<int> curve_set(const std::vector<UseFact>& loop) {
  std::set<int> s;
  for (const UseFact& u : loop) s.insert(u.curve);
  return s;
}

std::string vec_text(const geom::Vec3& v) {
  std::ostringstream s;
  s.precision(3);
  s << "(" << (std::abs(v.x()) < 5e-4 ? 0.0 : v.x()) << ", "
    << (std::abs(v.y()) < 5e-4 ? 0.0 : v.y()) << ", " << (std::abs(v.z()) < 5e-4 ? 0.0 : v.z())
    << ")";
  return s.str();
}

// A composite cap as a ranking sees it.
struct CapSize {
  int loops = 0;
  int curves = 0;
  double area = 0;
  bool shared = false;
  double holes = 0;  ///< length of its hole loops
};

// A sweep whose holes grow from source to target squashes the target's
// elements around them (the projection moves the hole's ring outward over
// elements sized for the smaller hole); shrinking holes only stretch them.
constexpr double kHoleGrowth = 1.25;

int compare_area(double x, double y) {
  if (std::abs(x - y) <= 1e-6 * std::max(std::abs(x), std::abs(y))) return 0;
  return x < y ? -1 : 1;
}

bool better_source(const CapSize& x, int xid, const CapSize& y, int yid) {
  if (x.loops != y.loops) return x.loops > y.loops;
  if (x.curves != y.curves) return x.curves > y.curves;
  if (const int c = compare_area(x.area, y.area)) return c > 0;
  return xid < yid;
}

}  // namespace

std::vector<int> hole_fillers(const VolumeFacts& facts, int host) {
  std::vector<int> out;
  const FaceFact* h = facts.face(host);
  for (size_t l = 1; l < h->loops.size(); ++l) {
    const std::set<int> hole = curve_set(h->loops[l]);
    for (const FaceFact& g : facts.faces) {
      if (g.id == host || curve_set(g.loops.front()) != hole) continue;
      bool flat = true;
      for (int c : hole) {
        const auto it = facts.dihedral.find(c);
        flat =
            flat && it != facts.dihedral.end() && std::abs(it->second - 180.0) <= kSubcapFlatness;
      }
      if (flat) {
        out.push_back(g.id);
        break;
      }
    }
  }
  return out;
}

// cite: Blacker 1996, sec. 3 (a sorting of the faces into sides and caps);
// sec. 4-5 (a cap made of subcaps).
std::vector<CapCandidate> pair_candidates(const VolumeFacts& facts, const std::vector<int>& sources,
                                          const std::vector<int>& targets, std::string& why) {
  // Composite caps: a host and the faces filling its hole loops (recursively).
  std::map<int, std::vector<int>> subcaps;
  std::set<int> absorbed;
  for (const FaceFact& f : facts.faces) {
    if (absorbed.count(f.id) || f.loops.size() < 2) continue;
    std::vector<int> todo = hole_fillers(facts, f.id);
    while (!todo.empty()) {
      const int g = todo.back();
      todo.pop_back();
      if (absorbed.count(g) || g == f.id) continue;
      absorbed.insert(g);
      subcaps[f.id].push_back(g);
      for (int k : hole_fillers(facts, g)) todo.push_back(k);
    }
  }
  auto host_of = [&](int id) {
    for (const auto& [h, list] : subcaps) {
      if (std::count(list.begin(), list.end(), id)) return h;
    }
    return id;
  };
  if (sources.size() > 1 || targets.size() > 1) {
    why = "the hints name " + std::to_string(std::max(sources.size(), targets.size())) +
          (sources.size() > 1 ? " sources" : " targets") + "; one barrel has one of each";
    return {};
  }
  for (int t : targets) {
    if (host_of(t) != t) {
      why = "hinted target surface " + std::to_string(t) + " is a subcap of surface " +
            std::to_string(host_of(t)) + "; a composite cap can only be the source";
      return {};
    }
  }
  const int hinted_source = sources.empty() ? 0 : host_of(sources.front());
  const int hinted_target = targets.empty() ? 0 : targets.front();
  std::map<int, CapSize> size;
  std::vector<int> forced, free;
  for (const FaceFact& f : facts.faces) {
    if (absorbed.count(f.id)) continue;
    free.push_back(f.id);
    CapSize s;
    std::vector<int> members{f.id};
    if (subcaps.count(f.id))
      members.insert(members.end(), subcaps[f.id].begin(), subcaps[f.id].end());
    std::set<std::set<int>> loops;  // the composite's boundary: loops not shared by two members
    std::map<std::set<int>, int> count;
    for (int m : members) {
      const FaceFact* mf = facts.face(m);
      s.area += mf->area;
      s.shared = s.shared || mf->other_volumes > 0;
      for (const auto& loop : mf->loops) ++count[curve_set(loop)];
    }
    const std::set<int> outer = curve_set(f.loops.front());
    for (const auto& [loop, n] : count) {
      if (n == 1) {
        ++s.loops;
        s.curves += static_cast<int>(loop.size());
        if (loop != outer) {
          for (int c : loop) s.holes += facts.curves.at(c).length;
        }
      }
    }
    size[f.id] = s;
    if (!f.submappable) forced.push_back(f.id);
  }
  if (forced.size() > 2) {
    why = "surfaces ";
    for (size_t i = 0; i < forced.size(); ++i) why += (i ? ", " : "") + std::to_string(forced[i]);
    why += " cannot be sides (several loops or not submappable), and one barrel has two caps";
    return {};
  }
  std::vector<CapCandidate> out;
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < free.size(); ++i) {
    for (size_t j = i + 1; j < free.size(); ++j) {
      const int a = free[i], b = free[j];
      bool ok = true;
      for (int f : forced) ok = ok && (f == a || f == b);
      for (int h : {hinted_source, hinted_target}) ok = ok && (h == 0 || h == a || h == b);
      if (ok) pairs.push_back({a, b});
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(), [&](const auto& x, const auto& y) {
    const int lx = size[x.first].loops + size[x.second].loops,
              ly = size[y.first].loops + size[y.second].loops;
    if (lx != ly) return lx > ly;
    const int cx = size[x.first].curves + size[x.second].curves,
              cy = size[y.first].curves + size[y.second].curves;
    if (cx != cy) return cx > cy;
    if (const int c = compare_area(size[x.first].area + size[x.second].area,
                                   size[y.first].area + size[y.second].area)) {
      return c > 0;
    }
    return x < y;
  });
  for (const auto& [a, b] : pairs) {
    const bool ca = subcaps.count(a) > 0, cb = subcaps.count(b) > 0;
    if (ca && cb) continue;  // one barrel: subcaps on one end only
    int src = better_source(size[a], a, size[b], b) ? a : b;
    int tgt = src == a ? b : a;
    if (size[tgt].shared && !size[src].shared) std::swap(src, tgt);
    bool fixed = false;
    if (subcaps.count(tgt)) {
      std::swap(src, tgt);
      fixed = true;
    }
    if (subcaps.count(src)) fixed = true;
    if (hinted_source || hinted_target) {
      if (hinted_source == tgt || hinted_target == src) std::swap(src, tgt);
      fixed = true;
    }
    if (!fixed && size[src].holes > 0 && size[tgt].holes > kHoleGrowth * size[src].holes)
      std::swap(src, tgt);
    if (subcaps.count(tgt)) {  // a hint asks a composite to be the target
      why = "hinted target surface " + std::to_string(tgt) +
            " has subcaps; a composite cap can only be the source";
      continue;
    }
    for (int flip = 0; flip < (fixed ? 1 : 2); ++flip) {
      CapCandidate c;
      c.kind = CapCandidate::Kind::Pair;
      c.source = flip ? tgt : src;
      c.target = flip ? src : tgt;
      c.fixed = fixed;
      c.caps = {a, b};
      for (int h : {a, b}) {
        if (subcaps.count(h)) c.caps.insert(subcaps[h].begin(), subcaps[h].end());
      }
      c.anchor.upper_cap = c.source;
      c.label = "one barrel from surface " + std::to_string(c.source) + " to surface " +
                std::to_string(c.target);
      out.push_back(std::move(c));
    }
  }
  if (out.empty() && why.empty()) {
    why = "no pair of caps fits the hints and the faces that cannot be sides (";
    for (size_t i = 0; i < forced.size(); ++i) why += (i ? ", " : "") + std::to_string(forced[i]);
    why += forced.empty() ? "none)" : ")";
  }
  return out;
}

std::vector<geom::Vec3> candidate_axes(const VolumeFacts& facts,
                                       const std::optional<geom::Vec3>& hint) {
  std::vector<geom::Vec3> axes;
  auto add = [&](geom::Vec3 d) {
    if (!(d.norm() > 0)) return;
    d.normalize();
    for (const auto& a : axes) {
      if (std::abs(a.dot(d)) > 0.999) return;
    }
    axes.push_back(d);
  };
  if (hint) {
    add(*hint);
    return axes;
  }
  for (const FaceFact& f : facts.faces) {
    if (f.loops.size() > 1 && f.planar) add(f.normal);
  }
  for (const FaceFact& f : facts.faces) {
    if (f.planar) add(f.normal);
  }
  return axes;
}

std::set<int> caps_facing(const VolumeFacts& facts, const geom::Vec3& axis) {
  const double c = std::cos(kCapFacing * kPi / 180.0);
  std::set<int> out;
  for (const FaceFact& f : facts.faces) {
    if (std::abs(f.normal.dot(axis.normalized())) > c) out.insert(f.id);
  }
  return out;
}

std::vector<CapCandidate> curved_candidates(const VolumeFacts& facts, size_t limit) {
  std::set<int> forced;
  std::vector<int> others;
  for (const FaceFact& f : facts.faces) {
    if (!f.submappable) {
      forced.insert(f.id);
    } else {
      others.push_back(f.id);
    }
  }
  std::vector<std::set<int>> sets;
  if (!forced.empty()) sets.push_back(forced);
  for (size_t i = 0; i < others.size() && sets.size() < limit; ++i) {
    std::set<int> s = forced;
    s.insert(others[i]);
    if (s.size() >= 2) sets.push_back(s);
  }
  for (size_t i = 0; i < others.size() && sets.size() < limit; ++i) {
    for (size_t j = i + 1; j < others.size() && sets.size() < limit; ++j) {
      std::set<int> s = forced;
      s.insert(others[i]);
      s.insert(others[j]);
      sets.push_back(s);
    }
  }
  std::vector<CapCandidate> out;
  for (const auto& s : sets) {
    if (s.size() < 2) continue;
    for (int flip = 0; flip < 2; ++flip) {
      CapCandidate c;
      c.kind = CapCandidate::Kind::Curved;
      c.caps = s;
      c.anchor.upper_cap = *s.begin();
      c.anchor.flip = flip == 1;
      c.label = "a curved sweep with caps ";
      for (int k : s) c.label += std::to_string(k) + (k == *s.rbegin() ? "" : ", ");
      out.push_back(std::move(c));
    }
  }
  return out;
}

std::vector<std::pair<int, geom::Vec3>> virtual_face_directions(const VolumeFacts& facts) {
  std::vector<std::pair<int, geom::Vec3>> out;
  for (const FaceFact& h : facts.faces) {
    if (!h.planar || h.loops.size() < 2) continue;
    for (size_t l = 1; l < h.loops.size(); ++l) {
      const std::set<int> hole = curve_set(h.loops[l]);
      std::set<int> ring;
      bool reentrant = true;
      std::set<int> loop_vertices;
      for (int c : hole) {
        const auto it = facts.dihedral.find(c);
        reentrant = reentrant && it != facts.dihedral.end() && it->second > kReentrantMin;
        for (int g : facts.faces_of_curve(c)) {
          if (g != h.id) ring.insert(g);
        }
        loop_vertices.insert(facts.curves.at(c).start);
        loop_vertices.insert(facts.curves.at(c).end);
      }
      if (!reentrant || ring.empty()) continue;
      geom::Vec3 sum = geom::Vec3::Zero();
      for (int g : ring) {
        for (const auto& loop : facts.face(g)->loops) {
          for (const UseFact& u : loop) {
            if (hole.count(u.curve)) continue;
            const CurveFact& c = facts.curves.at(u.curve);
            if (loop_vertices.count(c.start) && !loop_vertices.count(c.end)) {
              sum += (facts.vertices.at(c.end) - facts.vertices.at(c.start)).normalized();
            } else if (loop_vertices.count(c.end) && !loop_vertices.count(c.start)) {
              sum += (facts.vertices.at(c.start) - facts.vertices.at(c.end)).normalized();
            }
          }
        }
      }
      if (sum.norm() > 1e-9) out.push_back({h.id, sum.normalized()});
    }
  }
  return out;
}

std::string direction_text(const geom::Vec3& v) { return vec_text(v); }

}  // namespace cooperage::cooper
