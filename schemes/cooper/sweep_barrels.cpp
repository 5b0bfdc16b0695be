// Interior nodes and elements of every barrel (Blacker 1996, sec. 6.2-6.3):
// its upper cap mesh (the union of its upper subcaps' meshes) is swept to
// its lower cap mesh, whose nodes are all known from the stacks: the layers
// in between are the two-sided least-squares blend, elements are formed
// layer by layer from the cap faces and their ribs. The meshes of the caps
// this scheme meshed are handed back with their surfaces' natural normals.
#include "schemes/cooper/imprint_polygons.h"
#include "schemes/cooper/smooth_cap.h"
#include "schemes/cooper/sweep_barrel.h"
#include "schemes/cooper/sweep_state.h"
#include "schemes/cooper/sweep_volume.h"
#include "framework/core/log.h"

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>

namespace cooperage::cooper::detail {
namespace {

template <size_t N>
std::array<int, N> reversed(std::array<int, N> f) {
  std::reverse(f.begin() + 1, f.end());
  return f;
}

// Signed area of a face in the barrel's chart (upper end).
template <size_t N>
double area_2d(const SweepState& s, size_t b, const std::array<int, N>& f) {
  double a = 0;
  for (size_t k = 0; k < N; ++k) {
    const Vec2 p = s.plane(b, s.pos(f[k]));
    const Vec2 q = s.plane(b, s.pos(f[(k + 1) % N]));
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

// Node under each node of the upper piece: the faces of matched pieces
// correspond one for one (one was projected from the other).
template <size_t N>
void correspond(const std::vector<std::array<int, N>>& up,
                const std::vector<std::array<int, N>>& lo, NodeImage& below, int vid) {
  if (up.size() != lo.size()) fail(vid, "matched subcaps carry different meshes");
  for (size_t k = 0; k < up.size(); ++k) {
    for (size_t c = 0; c < N; ++c) {
      const auto [it, added] = below.emplace(up[k][c], lo[k][c]);
      if (!added && it->second != lo[k][c])
        fail(vid, "a cap node has two images across its barrel");
    }
  }
}

// Hands a barrel's sweep over to the volume's mesh: the rib nodes are
// looked up first (in layer order, as they were always numbered), then the
// interior layer nodes take consecutive slots layer by layer and the
// elements are renumbered in place. Every slot is fixed before the parallel
// loops run, so the mesh is the same for any thread count.
void append_sweep(SweepState& s, const BarrelState& st, const std::vector<int>& cap,
                  const NodeImage& below, SweepResult& sweep) {
  const size_t n = cap.size();
  const size_t B = st.ribs.size();
  const size_t J = static_cast<size_t>(st.layers);
  std::vector<int> rib_node(B * (J + 1));
  for (size_t j = 0; j <= J; ++j) {
    for (size_t i = 0; i < B; ++i) rib_node[j * B + i] = s.existing(st.ribs[i][j]);
  }
  std::vector<int> lower(n, -1);
  for (size_t i = B; i < n; ++i) lower[i] = below.at(cap[i]);
  const size_t inner = n - B;
  const size_t base = s.out.coords.size();
  const size_t fresh = J > 1 ? (J - 1) * inner : 0;
  scheme::EntityMesh& out = s.out;
  // The elements are renumbered first and the node map dropped before the
  // layer nodes are copied, and the node arrays grow after the sweep's points
  // are freed: the points and the volume's coordinates are the only per-node
  // arrays alive at once (the peak of a 10 M hex run, issue 20).
  {
    std::vector<int> node(sweep.points.size());
    tbb::parallel_for(size_t{0}, J + 1, [&](size_t j) {
      for (size_t i = 0; i < n; ++i) {
        const size_t q = j * n + i;
        if (i < B) {
          node[q] = rib_node[j * B + i];
        } else if (j == 0) {
          node[q] = cap[i];
        } else if (j == J) {
          node[q] = lower[i];
        } else {
          node[q] = static_cast<int>(base + (j - 1) * inner + (i - B));
        }
      }
    });
    auto renumber = [&](auto& elements) {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, elements.size(), 4096),
                        [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t e = r.begin(); e != r.end(); ++e) {
                            for (int& v : elements[e]) v = node[static_cast<size_t>(v)];
                          }
                        });
    };
    renumber(sweep.hexes);
    renumber(sweep.wedges);
  }
  // Room for the MeshDB's nodes as well: its commit then takes this array
  // over instead of copying it (MeshDB::append_nodes).
  out.coords.reserve(base + fresh + s.db.node_count());
  out.coords.resize(base + fresh);  // Vec3 is left uninitialised: every slot is written below
  if (J > 1) {
    tbb::parallel_for(size_t{1}, J, [&](size_t j) {
      std::copy(sweep.points.begin() + static_cast<std::ptrdiff_t>(j * n + B),
                sweep.points.begin() + static_cast<std::ptrdiff_t>(j * n + n),
                out.coords.begin() + static_cast<std::ptrdiff_t>(base + (j - 1) * inner));
    });
  }
  sweep.points = {};
  out.global.resize(base + fresh, -1);
  if (!out.owners.empty()) out.owners.resize(base + fresh);
  // The check's values go along while every barrel so far had them (a
  // smoothed barrel has none): one per element, or none at all.
  const size_t nh = sweep.hexes.size();
  const bool values = sweep.scaled_jacobian.size() == nh + sweep.wedges.size();
  auto carry = [&](std::vector<double>& to, size_t had, size_t first, size_t count) {
    if (!values || to.size() != had) {
      to = {};
    } else if (to.empty() && count == sweep.scaled_jacobian.size()) {
      to = std::move(sweep.scaled_jacobian);  // one barrel, one element type: no copy
    } else if (count > 0) {
      const auto from = sweep.scaled_jacobian.begin() + static_cast<std::ptrdiff_t>(first);
      to.insert(to.end(), from, from + static_cast<std::ptrdiff_t>(count));
    }
  };
  carry(out.hex_scaled_jacobian, out.hexes.size(), 0, nh);
  carry(out.wedge_scaled_jacobian, out.wedges.size(), nh, sweep.wedges.size());
  sweep.scaled_jacobian = {};
  auto append = [](auto& to, auto& from) {
    if (to.empty()) {
      to = std::move(from);  // the usual case, one barrel's elements: no copy
    } else {
      to.insert(to.end(), from.begin(), from.end());
    }
    from = {};
  };
  append(out.hexes, sweep.hexes);
  append(out.wedges, sweep.wedges);
}

}  // namespace

// cite: Blacker 1996, sec. 6.2 (x_ij = x^U_ij (1 - j/J) + x^L_ij j/J) and
// sec. 6.3 (elements from the cap stack faces and their ribs).
void sweep_barrels(SweepState& s, std::vector<BarrelReport>* reports) {
  for (size_t b = 0; b < s.barrels.size(); ++b) {
    BarrelState& st = s.barrels[b];
    std::vector<mesh::Quad> quads;
    std::vector<mesh::Tri> tris;
    size_t corners = st.rib_pairs.size();
    for (const auto& [u, l] : st.matches) {
      const Piece& pu = s.pieces[static_cast<size_t>(u)];
      corners += 4 * pu.quads.size() + 3 * pu.tris.size();
    }
    NodeImage below;
    below.reserve(corners);
    for (const auto& [u, l] : st.rib_pairs) below[u] = l;
    for (const auto& [u, l] : st.matches) {
      const Piece& pu = s.pieces[static_cast<size_t>(u)];
      const Piece& pl = s.pieces[static_cast<size_t>(l)];
      correspond(pu.quads, pl.quads, below, s.vid);
      correspond(pu.tris, pl.tris, below, s.vid);
      quads.insert(quads.end(), pu.quads.begin(), pu.quads.end());
      tris.insert(tris.end(), pu.tris.begin(), pu.tris.end());
    }
    weld_seam_images(s, b, below);
    // Cap nodes: the exterior rib starts in rib order, then the rest.
    SweepInput in;
    in.layers = st.layers;
    in.boundary = static_cast<int>(st.ribs.size());
    in.loop_starts = st.loop_starts;
    std::vector<int> cap;
    std::vector<int> rest;  // the faces' nodes, ascending
    rest.reserve(4 * quads.size() + 3 * tris.size());
    for (const auto& q : quads) rest.insert(rest.end(), q.begin(), q.end());
    for (const auto& t : tris) rest.insert(rest.end(), t.begin(), t.end());
    std::sort(rest.begin(), rest.end());
    rest.erase(std::unique(rest.begin(), rest.end()), rest.end());
    NodeImage index;
    index.reserve(st.ribs.size() + rest.size());
    for (const auto& rib : st.ribs) {
      index.emplace(s.existing(rib.front()), static_cast<int>(cap.size()));
      cap.push_back(s.existing(rib.front()));
    }
    for (int n : rest) {
      if (index.emplace(n, static_cast<int>(cap.size())).second) cap.push_back(n);
    }
    auto local = [&](int n) { return index.at(n); };
    for (const auto& q : quads) {
      mesh::Quad l{local(q[0]), local(q[1]), local(q[2]), local(q[3])};
      in.quads.push_back(area_2d(s, b, q) < 0 ? reversed(l) : l);
    }
    for (const auto& t : tris) {
      mesh::Tri l{local(t[0]), local(t[1]), local(t[2])};
      in.tris.push_back(area_2d(s, b, t) < 0 ? reversed(l) : l);
    }
    in.cap_nodes = static_cast<int>(cap.size());
    in.has_fixed_target.assign(cap.size(), 0);
    in.fixed_target.assign(cap.size(), Vec3::Zero());
    for (size_t i = 0; i < cap.size(); ++i) {
      in.source.push_back(s.pos(cap[i]));
      if (static_cast<int>(i) < in.boundary) continue;
      const auto it = below.find(cap[i]);
      if (it == below.end())
        fail(s.vid, s.barrel_name(b) + ": a node of its upper cap has no image on its lower cap");
      in.has_fixed_target[i] = 1;
      in.fixed_target[i] = s.pos(it->second);
    }
    for (const auto& rib : st.ribs) {
      for (int g : rib) in.ribs.push_back(s.db.node(g));
    }
    if (log::threshold() <= log::Level::Debug) {
      std::vector<Vec3> lo(in.source);
      for (size_t i = 0; i < cap.size(); ++i)
        lo[i] = i < st.ribs.size() ? s.db.node(st.ribs[i].back()) : in.fixed_target[i];
      log::debug("cooper, volume " + std::to_string(s.vid) + ", " + s.barrel_name(b) +
                 ": worst corner sine of its caps " +
                 std::to_string(min_quad_corner_quality(in.source, in.quads, st.d)) + " (upper), " +
                 std::to_string(min_quad_corner_quality(lo, in.quads, st.d)) + " (lower)");
    }
    SweepResult sweep = sweep_barrel(in);
    if (!sweep.ok) fail(s.vid, s.barrel_name(b) + ": " + sweep.why);
    if (log::threshold() <= log::Level::Debug) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "%s: %d layers, %zu quads, %zu triangles per layer, min scaled Jacobian %.4f%s",
                    s.barrel_name(b).c_str(), st.layers, in.quads.size(), in.tris.size(),
                    sweep.min_scaled_jacobian, sweep.smoothed ? " (smoothed)" : "");
      log::debug("cooper, volume " + std::to_string(s.vid) + ", " + line);
    }
    append_sweep(s, st, cap, below, sweep);
    if (reports) {
      BarrelReport r;
      r.barrel = static_cast<int>(b);
      r.layers = st.layers;
      r.min_scaled_jacobian = sweep.min_scaled_jacobian;
      r.smoothed = sweep.smoothed;
      r.imprint_steps = st.steps;
      for (const EndPiece& e : s.plan.tree.barrels[b].upper) {
        if (e.cap) r.upper_caps.push_back(e.cap);
      }
      reports->push_back(std::move(r));
    }
  }
  // The caps meshed here, with their natural normals.
  for (const Piece& p : s.pieces) {
    if (!p.alive || !p.cap || p.premeshed) continue;
    const auto& g = *s.model.surface(p.cap).geometry;
    auto natural = [&](auto f) {
      Vec3 c = Vec3::Zero();
      for (int k : f) c += s.pos(k) / static_cast<double>(f.size());
      Vec3 nrm = Vec3::Zero();
      for (size_t k = 0; k < f.size(); ++k) nrm += s.pos(f[k]).cross(s.pos(f[(k + 1) % f.size()]));
      return nrm.dot(g.project(c).normal) >= 0 ? f : reversed(f);
    };
    for (const auto& q : p.quads) s.out.surface_quads[p.cap].push_back(natural(q));
    for (const auto& t : p.tris) s.out.surface_tris[p.cap].push_back(natural(t));
  }
}

}  // namespace cooperage::cooper::detail
