// Candidate cuts of a volume (issue 17): the planes of its own planar faces
// (extended), the cylinders of its cylindrical faces, planes through its
// straight feature edges along the candidate sweep axes (the normals of its
// planar faces and the axes of its cylinders), and cones through pairs of
// its tangent circular edges (cone_candidates.h). Blacker 1996, sec. 3: the
// user's hand decomposition of Fig. 3a is such a cut, through the plane of a
// boss's side face, so that each piece projects along one axis.
#pragma once

#include "framework/decompose/cut_surface.h"
#include "framework/geometry/model.h"

#include <string>
#include <vector>

namespace cooperage::decompose {

struct CutCandidate {
  CutSurface surface;
  /// Where it comes from, for a person: "plane of surface 12",
  /// "cylinder of surface 9", "plane through curve 7 along z" (ids of the
  /// model it was found in; the search names the part's, part_ids.h).
  std::string through;
};

struct CandidateOptions {
  /// Sweep axes tried for planes through edges, the most face area first.
  int max_axes = 6;
  /// A straight edge is a feature edge when the outward normals of its two
  /// faces differ by more than this (degrees).
  double feature_angle_deg = 20.0;
  /// Two candidates closer than this (model units) are one.
  double tolerance = 1e-6;
};

/// Candidates in a deterministic order that depends only on the topology
/// (ids), not on the placement of the part: face planes (surface order),
/// then cylinders, then planes through edges (axis order, curve order),
/// then cones (curve order).
/// Duplicates (the same surface from several faces or edges) appear once,
/// under their first source.
std::vector<CutCandidate> cut_candidates(const geom::Model& model, int volume,
                                         const CandidateOptions& options = {});

/// Meridian planes: for each distinct axis of its cylindrical and toroidal
/// faces, one plane holding it. A solid of revolution that no axial sweep takes (a
/// concave blend, a dome) is two halves swept round the axis, each ending
/// on the other's source (a ring of sweeps); tried only when the other
/// candidates find nothing, since where they do their pieces sweep better.
std::vector<CutCandidate> meridian_candidates(const geom::Model& model, int volume,
                                              const CandidateOptions& options = {});

/// A turned part solid at its axis: a core cylinder about the axis of its
/// cylindrical faces, of half the smallest of their radii (swept along the
/// axis), and a meridian plane for the tube left around it (its halves
/// swept round the axis). Their halves of a meridian cut alone would hold
/// the axis, which no sweep round it takes.
struct CoreCut {
  CutCandidate core;
  CutCandidate meridian;
};
std::vector<CoreCut> core_candidates(const geom::Model& model, int volume,
                                     const CandidateOptions& options = {});

/// The candidate sweep axes of a volume: unit normals of its planar faces
/// and axes of its cylindrical faces, parallel ones merged (the sign of the
/// first kept), ordered by the area of the faces behind them (largest
/// first; ties by first appearance).
std::vector<geom::Vec3> sweep_axes(const geom::Model& model, int volume);

}  // namespace cooperage::decompose
