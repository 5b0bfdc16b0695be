#include "schemes/pave/halfedge_cleanup.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace cooperage::pave::detail {
namespace {

/// Double coordinates (z = 0) and the status bits that deletion needs.
struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
};
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<Traits>;
using VH = Mesh::VertexHandle;
using FH = Mesh::FaceHandle;
using HH = Mesh::HalfedgeHandle;
using Corners = std::array<VH, 4>;

/// FASTQ's quad count for a boundary angle [deg] (as irregular_nodes()).
int ideal_quads(double degrees) {
  return degrees < 135 ? 1 : degrees < 225 ? 2 : degrees < 315 ? 3 : 4;
}

class Cleaner {
 public:
  Cleaner(const std::vector<Eigen::Vector2d>& points, const std::vector<Quad>& quads,
          const std::vector<char>& fixed, const HalfEdgeCleanupOptions& options)
      : fixed_(fixed), ideal_(points.size(), 4), options_(options) {
    for (const auto& p : points) m_.add_vertex(Mesh::Point(p.x(), p.y(), 0.0));
    std::vector<double> angle(points.size(), 0.0);
    for (size_t k = 0; k < quads.size(); ++k) {
      const Quad& q = quads[k];
      if (!m_.add_face(vh(q[0]), vh(q[1]), vh(q[2]), vh(q[3])).is_valid())
        throw std::runtime_error("quad " + std::to_string(k) +
                                 " does not fit a manifold half-edge mesh");
      for (size_t c = 0; c < 4; ++c) {
        const Eigen::Vector2d o = points[static_cast<size_t>(q[c])];
        const Eigen::Vector2d e0 = points[static_cast<size_t>(q[(c + 1) % 4])] - o;
        const Eigen::Vector2d e1 = points[static_cast<size_t>(q[(c + 3) % 4])] - o;
        angle[static_cast<size_t>(q[c])] += std::atan2(cross2(e0, e1), e0.dot(e1));
      }
    }
    for (size_t i = 0; i < points.size(); ++i) {
      if (fixed_[i]) ideal_[i] = ideal_quads(angle[i] * 180.0 / M_PI);
    }
  }

  HalfEdgeCleanupCounts run() {
    for (int pass = 0; pass < options_.max_passes; ++pass) {
      const HalfEdgeCleanupCounts before = counts_;
      doublets();
      diamonds();
      if (options_.rotate) rotations();
      if (before.doublets == counts_.doublets && before.diamonds == counts_.diamonds &&
          before.rotations == counts_.rotations)
        break;
    }
    return counts_;
  }

  /// The live vertices in index order and the live faces in index order.
  void write_back(std::vector<Eigen::Vector2d>& points, std::vector<Quad>& quads,
                  std::vector<char>& fixed) const {
    std::vector<int> remap(m_.n_vertices(), -1);
    points.clear();
    fixed.clear();
    for (size_t i = 0; i < m_.n_vertices(); ++i) {
      const VH v = vh(static_cast<int>(i));
      if (m_.status(v).deleted() || (!fixed_[i] && m_.is_isolated(v))) continue;
      remap[i] = static_cast<int>(points.size());
      points.push_back(pos(v));
      fixed.push_back(fixed_[i]);
    }
    quads.clear();
    for (size_t k = 0; k < m_.n_faces(); ++k) {
      const FH f = m_.face_handle(static_cast<unsigned>(k));
      if (m_.status(f).deleted()) continue;
      // add_face() gives a face its last half-edge: start at the next one,
      // so that an untouched quad keeps its first corner.
      const Corners c = corners(m_.next_halfedge_handle(m_.halfedge_handle(f)));
      Quad q;
      for (size_t j = 0; j < 4; ++j) q[j] = remap[static_cast<size_t>(c[j].idx())];
      quads.push_back(q);
    }
  }

 private:
  VH vh(int i) const { return m_.vertex_handle(static_cast<unsigned>(i)); }
  Eigen::Vector2d pos(VH v) const {
    const Mesh::Point& p = m_.point(v);
    return {p[0], p[1]};
  }
  bool is_fixed(VH v) const { return fixed_[static_cast<size_t>(v.idx())] != 0; }
  double quality(const Corners& c) const {
    return scaled_jacobian_2d(pos(c[0]), pos(c[1]), pos(c[2]), pos(c[3]));
  }

  /// The corners of a face, starting at the origin of h (faces are quads).
  Corners corners(HH h) const {
    Corners c;
    for (size_t j = 0; j < 4; ++j, h = m_.next_halfedge_handle(h)) c[j] = m_.from_vertex_handle(h);
    return c;
  }
  bool is_quad(HH h) const {
    return m_.next_halfedge_handle(
               m_.next_halfedge_handle(m_.next_halfedge_handle(m_.next_halfedge_handle(h)))) == h;
  }
  int quads_at(VH v) const {
    int n = 0;
    for (const HH h : m_.voh_range(v)) n += m_.face_handle(h).is_valid();
    return n;
  }
  std::vector<FH> faces_at(VH v) const {
    std::vector<FH> out;
    for (const HH h : m_.voh_range(v)) {
      if (m_.face_handle(h).is_valid()) out.push_back(m_.face_handle(h));
    }
    return out;
  }
  /// How far nodes' quad counts are from their ideal: the sum of the
  /// deviations and the number of nodes that deviate.
  struct Irregularity {
    int sum = 0, count = 0;
    Irregularity operator+(const Irregularity& o) const { return {sum + o.sum, count + o.count}; }
    /// A lower sum without more irregular nodes.
    bool better_than(const Irregularity& o) const { return sum < o.sum && count <= o.count; }
  };
  /// The irregularity of v with `n` quads.
  Irregularity at(VH v, int n) const {
    const int d = std::abs(n - ideal_[static_cast<size_t>(v.idx())]);
    return {d, d != 0};
  }
  /// A change is kept when its quads are valid and their worst is not pushed
  /// below min(threshold, worst before).
  bool acceptable(double worst_after, double worst_before) const {
    return worst_after > 0 && worst_after >= std::min(options_.min_quality, worst_before);
  }

  /// Deletes `old` faces (and `dead`, left isolated), adds `fresh`; throws
  /// when OpenMesh refuses a face (the checks before should prevent it).
  void replace(const std::vector<FH>& old, VH dead, const std::vector<Corners>& fresh,
               const char* what) {
    for (const FH f : old) m_.delete_face(f, false);
    if (dead.is_valid()) m_.delete_vertex(dead, false);
    for (const Corners& c : fresh) {
      if (!m_.add_face(c[0], c[1], c[2], c[3]).is_valid())
        throw std::runtime_error(std::string("pave clean-up: a ") + what + " at node " +
                                 std::to_string(c[0].idx()) + " broke the half-edge mesh");
    }
  }

  /// Doublets: a free node v in exactly two quads (v, x, y, z), (v, z, w, x)
  /// leaves; the quads merge into (x, y, z, w).
  void doublets() {
    for (size_t i = 0; i < m_.n_vertices(); ++i) {
      const VH v = vh(static_cast<int>(i));
      if (m_.status(v).deleted() || is_fixed(v) || m_.is_boundary(v) || m_.valence(v) != 2)
        continue;
      const HH h = m_.halfedge_handle(v), o = m_.opposite_halfedge_handle(h);
      if (!is_quad(h) || !is_quad(o)) continue;
      const Corners a = corners(h);  // v, x, y, z
      const Corners b = corners(o);  // x, v, z, w
      if (b[2] != a[3]) continue;
      const Corners merged{a[1], a[2], a[3], b[3]};
      if (merged[1] == merged[3]) continue;
      const double before = std::min(quality(a), quality(b));
      if (!acceptable(quality(merged), before)) continue;
      replace({m_.face_handle(h), m_.face_handle(o)}, v, {merged}, "doublet removal");
      ++counts_.doublets;
    }
  }

  /// Diamonds: quad (a, b, c, d) with free interior a, c in three quads each
  /// and no other shared neighbour; c merges into a at the diagonal's middle.
  void diamonds() {
    for (size_t k = 0; k < m_.n_faces(); ++k) {
      const FH f = m_.face_handle(static_cast<unsigned>(k));
      if (m_.status(f).deleted()) continue;
      HH h = m_.halfedge_handle(f);
      if (!is_quad(h)) continue;
      for (int r = 0; r < 2; ++r, h = m_.next_halfedge_handle(h)) {
        if (try_diamond(f, corners(h))) break;
      }
    }
  }

  bool try_diamond(FH f, const Corners& q) {
    const VH a = q[0], b = q[1], c = q[2], d = q[3];
    for (const VH v : {a, c}) {
      if (is_fixed(v) || m_.is_boundary(v) || m_.valence(v) != 3) return false;
    }
    // a's and c's third neighbours must differ (else two edges would join
    // the same nodes), and their quads must meet only in f.
    std::vector<VH> na, nc;
    for (const VH w : m_.vv_range(a)) na.push_back(w);
    for (const VH w : m_.vv_range(c)) nc.push_back(w);
    for (const VH w : na) {
      if (w != b && w != d && std::find(nc.begin(), nc.end(), w) != nc.end()) return false;
    }
    const std::vector<FH> fa = faces_at(a), fc = faces_at(c);
    for (const FH g : fa) {
      if (g != f && std::find(fc.begin(), fc.end(), g) != fc.end()) return false;
    }
    if (!options_.boundary_counts && (is_fixed(b) || is_fixed(d))) return false;
    const int qb = quads_at(b), qd = quads_at(d);
    const Irregularity before = Irregularity{} + at(a, 3) + at(c, 3) + at(b, qb) + at(d, qd);
    const Irregularity after = Irregularity{} + at(a, 4) + at(b, qb - 1) + at(d, qd - 1);
    if (!after.better_than(before)) return false;

    std::vector<Corners> fresh;  // c's other quads with c -> a
    double worst_before = 1.0;
    for (const FH g : fc) {
      worst_before = std::min(worst_before, quality(corners(m_.halfedge_handle(g))));
      if (g == f) continue;
      Corners t = corners(m_.halfedge_handle(g));
      if (!is_quad(m_.halfedge_handle(g))) return false;
      for (VH& v : t) v = v == c ? a : v;
      fresh.push_back(t);
    }
    std::vector<Corners> kept;  // a's other quads
    for (const FH g : fa) {
      if (g == f) continue;
      kept.push_back(corners(m_.halfedge_handle(g)));
      worst_before = std::min(worst_before, quality(kept.back()));
    }
    const Mesh::Point saved = m_.point(a);
    m_.set_point(a, 0.5 * (saved + m_.point(c)));
    double worst_after = 1.0;
    for (const Corners& t : fresh) worst_after = std::min(worst_after, quality(t));
    for (const Corners& t : kept) worst_after = std::min(worst_after, quality(t));
    if (!acceptable(worst_after, worst_before)) {
      m_.set_point(a, saved);
      return false;
    }
    std::vector<FH> old{f};
    for (const FH g : fc) {
      if (g != f) old.push_back(g);
    }
    replace(old, c, fresh, "diamond collapse");
    ++counts_.diamonds;
    return true;
  }

  /// Edge rotation: the quads (u, v, x1, x2) and (v, u, y1, y2) of edge u-v
  /// form the hexagon H = (v, x1, x2, u, y1, y2); the shared edge H0-H3 may
  /// move to H1-H4 or H2-H5. u and v lose a quad, the new diagonal's ends
  /// gain one.
  void rotations() {
    for (size_t e = 0; e < m_.n_edges(); ++e) {
      const auto eh = m_.edge_handle(static_cast<unsigned>(e));
      if (m_.status(eh).deleted() || m_.is_boundary(eh)) continue;
      try_rotation(m_.halfedge_handle(eh, 0));
    }
  }

  void try_rotation(HH h) {
    const HH o = m_.opposite_halfedge_handle(h);
    if (!is_quad(h) || !is_quad(o)) return;
    const Corners f1 = corners(h);  // u, v, x1, x2
    const Corners f2 = corners(o);  // v, u, y1, y2
    const std::array<VH, 6> H{f1[1], f1[2], f1[3], f1[0], f2[2], f2[3]};
    for (size_t i = 0; i < 6; ++i) {
      for (size_t j = i + 1; j < 6; ++j) {
        if (H[i] == H[j]) return;
      }
    }
    std::array<int, 6> n{};
    Irregularity before;
    for (size_t i = 0; i < 6; ++i) {
      n[i] = quads_at(H[i]);
      before = before + at(H[i], n[i]);
    }
    const double worst_before = std::min(quality(f1), quality(f2));
    Irregularity best_after = before;
    double best_worst = 0;
    std::array<Corners, 2> best;
    for (size_t s = 1; s <= 2; ++s) {  // new diagonal H[s] - H[s + 3]
      if (m_.find_halfedge(H[s], H[s + 3]).is_valid()) continue;
      if (!options_.boundary_counts &&
          (is_fixed(H[0]) || is_fixed(H[3]) || is_fixed(H[s]) || is_fixed(H[s + 3])))
        continue;
      std::array<int, 6> m = n;
      --m[0];
      --m[3];
      ++m[s];
      ++m[s + 3];
      Irregularity after;
      for (size_t i = 0; i < 6; ++i) after = after + at(H[i], m[i]);
      if (!after.better_than(before)) continue;
      const std::array<Corners, 2> quads{Corners{H[s], H[s + 1], H[s + 2], H[s + 3]},
                                         Corners{H[s + 3], H[(s + 4) % 6], H[(s + 5) % 6], H[s]}};
      const double worst = std::min(quality(quads[0]), quality(quads[1]));
      if (!acceptable(worst, worst_before)) continue;
      const bool same = after.sum == best_after.sum && after.count == best_after.count;
      if (after.better_than(best_after) || (same && worst > best_worst)) {
        best_after = after;
        best_worst = worst;
        best = quads;
      }
    }
    if (!best_after.better_than(before)) return;
    replace({m_.face_handle(h), m_.face_handle(o)}, VH(), {best[0], best[1]}, "edge rotation");
    ++counts_.rotations;
  }

  Mesh m_;
  std::vector<char> fixed_;
  std::vector<int> ideal_;  // quads a node should have (4 inside)
  HalfEdgeCleanupOptions options_;
  HalfEdgeCleanupCounts counts_;
};

}  // namespace

HalfEdgeCleanupCounts halfedge_cleanup(std::vector<Eigen::Vector2d>& points,
                                       std::vector<Quad>& quads, std::vector<char>& fixed,
                                       const HalfEdgeCleanupOptions& options) {
  Cleaner cleaner(points, quads, fixed, options);
  const HalfEdgeCleanupCounts counts = cleaner.run();
  cleaner.write_back(points, quads, fixed);
  return counts;
}

}  // namespace cooperage::pave::detail
