// What the cooper classification needs to know about one volume, gathered
// once from the model (Blacker 1996, sec. 3: "a simple calculation based on
// topology and angle designations"): loops, corner angles, the dihedral
// angle at every curve between two of its faces, normals, sampled curves.
// gather_facts() is the only classification step that reads CAD; every
// later step (side_lattice.h, sweep_order.h, slab_regions.h,
// barrel_tree.h, cap_roles.h) works on these plain values and is
// unit-tested with hand-made facts.
#pragma once

#include "framework/geometry/model.h"
#include "framework/scheme/registry.h"
#include "schemes/cooper/tangent_departure.h"

#include <map>
#include <string>
#include <vector>

namespace cooperage::cooper {

/// A curve use in a face loop.
struct UseFact {
  int curve = 0;
  bool forward = true;  ///< walked from the curve's start vertex to its end
};

struct FaceFact {
  int id = 0;
  std::vector<std::vector<UseFact>> loops;  ///< outer loop first
  /// Single-loop faces: interior angle [degrees] at corner k (before use k).
  std::vector<double> angles;
  bool planar = false;
  geom::Vec3 normal = geom::Vec3::Zero();  ///< unit, out of the volume, at the face's centre
  geom::Vec3 centre = geom::Vec3::Zero();  ///< the point of the face nearest its area centroid
  /// The area centroid itself: off the face where it curves (a whole
  /// cylinder's lies on its axis, inside a hole's wall, outside a boss's).
  geom::Vec3 centroid = geom::Vec3::Zero();
  double area = 0;
  /// The registry's submap accepts it (single loop): it may be a side.
  bool submappable = false;
  double submap_score = 0;
  std::string submap_why;
  /// Other volumes it bounds (an interface of an assembly): its mesh is
  /// shared, so it must come from a surface scheme, never from this sweep.
  int other_volumes = 0;
  /// Single-loop faces, from `angles` (type_corners() in side_lattice.h):
  /// the lattice direction of each use from the corners' own types (empty,
  /// with `directions_why`, when they give none), and whether a corner fits
  /// two types so that the neighbours decide. Kept here because every
  /// sorting of the faces into caps and sides asks again.
  std::vector<int> directions;
  std::string directions_why;
  bool ambiguous_corners = false;
};

struct CurveFact {
  int id = 0;
  int start = 0;  ///< vertex ids
  int end = 0;
  double length = 0;
  /// Points along the curve, start to end (for outlines and directions).
  std::vector<geom::Vec3> samples;
};

struct VolumeFacts {
  int volume = 0;
  int shells = 1;
  std::vector<FaceFact> faces;  ///< ascending id
  std::map<int, CurveFact> curves;
  std::map<int, geom::Vec3> vertices;
  /// Interior dihedral angle [degrees, (0, 360)] inside the volume at a
  /// curve shared by two of its faces (90 at a brick edge, 270 re-entrant).
  std::map<int, double> dihedral;
  /// At curves whose dihedral is tangent (kMaxCapDihedral..kReentrantMin):
  /// how each of the two faces leaves the other (both ways).
  std::vector<TangentDeparture> departures;

  const FaceFact* face(int id) const;
  /// Faces of the volume whose loops use the curve (ascending, once each).
  std::vector<int> faces_of_curve(int curve) const;
  /// Span of the vertices and curve samples (a length scale for
  /// tolerances): a long chord of the point set, the same for a moved part.
  /// gather_facts() keeps it in `known_size`; hand-made facts measure it.
  double size() const;
  double span() const;
  double known_size = 0;
  /// Diagonal of the box of the given curves' samples (0 for none).
  double extent(const std::vector<int>& curve_ids) const;
};

/// Gathers the facts of `volume_id`; the submap verdicts come from the
/// registry's "submap" (none when it is not registered).
/// `settings` reach submap's applicable() (its vertex types); null: defaults.
VolumeFacts gather_facts(const geom::Model& model, int volume_id, const scheme::Registry& registry,
                         const scheme::Settings* settings = nullptr);

}  // namespace cooperage::cooper
