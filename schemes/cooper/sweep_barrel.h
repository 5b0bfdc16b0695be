// The one-barrel sweep core (Blacker 1996, sec. 6.2-6.3): interior layer
// nodes by the two-sided least-squares blend, target cap nodes projected
// from the source, hexes (quad caps) and wedges (triangle caps) layer by
// layer, with an inversion check and a smoothing fallback. Value types only:
// contiguous arrays, no CAD (the target surface comes in as a callback).
#pragma once

#include "framework/mesh/mesh_db.h"
#include "schemes/cooper/least_squares_map.h"

#include <functional>
#include <string>
#include <vector>

namespace cooperage::cooper {

/// One barrel: a source cap mesh and the ribs of its boundary nodes.
/// Local cap nodes 0..cap_nodes-1; the first `boundary` of them are the rib
/// starts in rib order, the rest are interior cap nodes.
struct SweepInput {
  int cap_nodes = 0;
  int boundary = 0;
  /// First rib of every boundary loop (first entry 0), for the pseudo-areas.
  std::vector<std::size_t> loop_starts;
  /// Positions of the cap nodes on the source (layer 0) [model units].
  std::vector<Vec3> source;
  int layers = 0;  ///< J >= 1
  /// Rib positions: rib r at layer j is ribs[r * (layers + 1) + j]; layer 0
  /// equals source[r], layer J lies on the target cap's boundary.
  std::vector<Vec3> ribs;
  /// Source cap elements in local cap indices, oriented counter-clockwise
  /// about the direction INTO the volume (towards layer 1).
  std::vector<mesh::Quad> quads;
  std::vector<mesh::Tri> tris;
  /// Closest point on the target surface; identity when empty. Called only
  /// for interior target cap nodes.
  std::function<Vec3(const Vec3&)> project_target;
  /// Empty, or one flag per cap node: the node's target position is known
  /// (`fixed_target[i]`), e.g. the far end of an interior rib onto an
  /// existing lower subcap (Blacker 1996, sec. 5.2, 6.2); it is never moved.
  std::vector<char> has_fixed_target;
  std::vector<Vec3> fixed_target;
};

struct SweepOptions {
  /// Elements with a scaled Jacobian at or below this count as inverted.
  double min_scaled_jacobian = 1e-6;
  /// Below this minimum scaled Jacobian the smoothing fallback is tried as
  /// well and the better placement kept.
  double improve_below = 0.2;
  /// Laplacian iterations of the smoothing fallback per layer.
  int smoothing_iterations = 60;
};

struct SweepResult {
  bool ok = false;
  std::string why;  ///< reason for !ok, e.g. "hex 12 of layer 3 inverted"
  /// Node i of layer j is points[j * cap_nodes + i].
  std::vector<Vec3> points;
  std::vector<mesh::Hex> hexes;      ///< indices into points, Exodus order
  std::vector<mesh::Wedge> wedges;   ///< indices into points, Exodus order
  double min_scaled_jacobian = 1.0;  ///< over all elements
  bool smoothed = false;             ///< the smoothing fallback was needed
  /// The scaled Jacobian of every hex, then every wedge, on `points` as
  /// handed over (the run's quality report takes them instead of computing
  /// them again). Empty after a smoothing fallback: the fallbacks move the
  /// target layer, whose nodes the mesh takes from the lower cap instead.
  std::vector<double> scaled_jacobian;
};

/// Layer nodes: layer 0 = source, rib nodes from the ribs, interior target
/// nodes = the source least-squares map to the target loop, projected onto
/// the target surface; interior layers x_ij = x^U_ij (1 - s_j) + x^L_ij s_j
/// with s_j the mean arc-length fraction along the ribs (graded layers).
/// Where the loops' motion is not affine (residuals above 1e-9 of the ring
/// size, e.g. a hole that does not shrink with the outer loop), the loop
/// residuals are carried to the interior by inverse-distance weights.
/// \return false (why set) when a least-squares map is singular or inverts.
bool place_layer_nodes(const SweepInput& in, std::vector<Vec3>& points, std::string& why);

/// The interior layers of place_layer_nodes (the two-sided blend with the
/// loop residuals) from the source and target layers already in `points`,
/// e.g. after the target layer was smoothed.
/// \return false (why set) when a least-squares map to a layer is singular.
bool blend_layers(const SweepInput& in, std::vector<Vec3>& points, std::string& why);

/// Hexes from quads and wedges from triangles, layer by layer (points
/// indexing as in SweepResult).
void make_elements(const SweepInput& in, std::vector<mesh::Hex>& hexes,
                   std::vector<mesh::Wedge>& wedges);

/// Minimum scaled Jacobian of the elements (Verdict), and the first element
/// at or below `limit` (-1 when none): hexes first, then wedges.
/// \param[out] values  when given, every element's value in that order
double min_scaled_jacobian(const std::vector<Vec3>& points, const std::vector<mesh::Hex>& hexes,
                           const std::vector<mesh::Wedge>& wedges, double limit, long* first_bad,
                           std::vector<double>* values = nullptr);

/// Fallback placement: Laplacian smoothing of the interior nodes of every
/// interior layer (and of the target layer, re-projected), rib nodes fixed.
void smooth_layers(const SweepInput& in, int iterations, std::vector<Vec3>& points);

/// The other fallback: Laplacian smoothing of the target layer only
/// (re-projected, fixed targets kept), then blend_layers. The interior
/// layers keep the source cap's shape near the source instead of all
/// converging to one smoothed layer. \return false as blend_layers.
bool smooth_target_then_blend(const SweepInput& in, int iterations, std::vector<Vec3>& points);

/// place_layer_nodes + make_elements + the inversion check; when an element
/// is inverted (or the minimum scaled Jacobian is below improve_below),
/// smooth_target_then_blend and smooth_layers, keeping the best placement.
/// ok is false (why set) when elements stay inverted: never emits inverted
/// elements silently.
SweepResult sweep_barrel(const SweepInput& in, const SweepOptions& options = {});

}  // namespace cooperage::cooper
