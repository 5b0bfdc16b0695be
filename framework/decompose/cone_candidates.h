// Conical cuts through two coaxial circles where a volume's faces meet
// tangently (issue 16 item 3, a flanged dome): the cone from the flange's
// inner rim on one side to the fillet's rim on the other separates the
// flange from the dome, so that each piece sweeps (the flange along its
// axis, the dome through its thickness). Planes and cylinders cannot make
// that cut.
#pragma once

#include "framework/decompose/cut_candidates.h"

#include <optional>
#include <vector>

namespace cooperage::decompose {

using geom::Vec3;

/// A closed curve of the model that lies on a circle: the circle and the
/// largest distance of the curve's samples from it (B-spline circles of a
/// CAD model are circles only to their fitting error).
struct CircleFit {
  Vec3 centre = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double radius = 0.0;
  double error = 0.0;
};

/// The circle of curve `c` when it is closed and within 1e-3 of its radius
/// of a circle; nullopt otherwise.
std::optional<CircleFit> circle_of(const geom::Model& model, int c);

/// Cones through pairs of tangent circular curves of `volume` (the faces on
/// both sides meet within `tangent_deg` of flat) that share an axis and
/// differ in both radius and height, bound no common face, and whose cone
/// leaves the faces at both circles at 30 degrees or more. Ordered by
/// curve ids; at most `max_cones`. Each cone's seam runs through the first
/// curve's start vertex, and its fuzzy distance covers both fits' errors.
std::vector<CutCandidate> cone_candidates(const geom::Model& model, int volume,
                                          double tangent_deg = 10.0, int max_cones = 12);

}  // namespace cooperage::decompose
